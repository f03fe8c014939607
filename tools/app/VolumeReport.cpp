#include "tools/app/VolumeReport.h"

#include "io/ElementQuality.h"
#include "mesher/volume/VolumeControlSpace.h"

namespace aniso::app {

namespace {

nlohmann::ordered_json recoveryJson(const RecoveryStats& s) {
  nlohmann::ordered_json j;
  j["phases"] = {"pipe-reduction", "interior-cavity"};
  j["edges"] = s.edges;
  j["faces"] = s.faces;
  j["missing_edges"] = s.missingEdges;
  j["missing_faces"] = s.missingFaces;
  j["edges_recovered"] = s.edgesRecovered;
  j["faces_recovered"] = s.facesRecovered;
  j["steiner_points_inside"] = s.steinerPoints;
  j["flips23"] = s.flips.flips23;
  j["edge_removals"] = s.flips.removals;
  return j;
}

nlohmann::ordered_json statsJson(const QualityStats& s) {
  return {{"mean", s.count() ? s.mean() : 0.0}, {"sd", s.stddev()}, {"min", s.count() ? s.min() : 0.0},
          {"max", s.count() ? s.max() : 0.0}};
}

nlohmann::ordered_json qualityJson(const TetQualitySummary& q) {
  nlohmann::ordered_json j;
  j["mean_ratio"] = statsJson(q.meanRatio);
  j["dihedral_min"] = q.minDihedral;
  j["dihedral_max"] = q.maxDihedral;
  j["referee_dihedral_min"] = q.refereeMinDihedral;
  j["tets_below_5deg"] = q.belowDihedral;
  j["inverted"] = q.inverted;
  j["eta_M"] = statsJson(q.etaM);
  j["mu_M"] = statsJson(q.muM);            // in M_v, the metric of the tets (VolumeControlSpace.h)
  j["mu_M_user"] = statsJson(q.muMUser);  // in the user's metric M = f M_v
  return j;
}

}  // namespace

void fillVolumeReport(const Model& model, const VolumeMeshResult& vr, io::Report& report) {
  report.nodes = static_cast<long long>(vr.mesh.nodes().size());
  report.tetrahedra = static_cast<long long>(vr.mesh.tets.size());
  report.triangles = static_cast<long long>(vr.mesh.surface.triangles.size());  // with boundary splits
  report.extra["recovery"] = recoveryJson(vr.recovery);
  report.extra["recovery"]["steiner_points_boundary"] = vr.boundarySplits;
  report.extra["recovery"]["split_rounds"] = vr.splitRounds;
  report.extra["recovery"]["surface_folds_repaired"] = vr.foldsRepaired;
  report.extra["recovery"]["surface_nodes_merged"] = vr.surfaceNodesMerged;
  report.extra["recovery"]["surface_caps_flipped"] = vr.surfaceCapsFlipped;
  std::vector<int> crackIds;
  for (const int f : vr.cracks.faces) crackIds.push_back(f + 1);
  report.extra["cracks"] = {{"faces", vr.cracks.crackFaces},
                            {"face_ids", crackIds},
                            {"nodes_duplicated", vr.cracks.nodesDuplicated},
                            {"triangles_added", vr.cracks.trianglesAdded}};
  report.quality["volume"] = qualityJson(vr.quality);
  report.quality["elements"] = io::elementQuality(vr.mesh);
  report.quality["volume"]["length_factor"] = kVolumeLengthFactor;
  report.extra["volume"] = vr.quality.volume;
  nlohmann::ordered_json solids = nlohmann::ordered_json::array();
  for (std::size_t s = 0; s < vr.solids.size(); ++s) {
    const SolidOutcome& o = vr.solids[s];
    nlohmann::ordered_json j;
    j["solid"] = s + 1;
    j["name"] = s < model.solids.size() ? model.solids[s].name : std::string();
    j["status"] = o.status == SolidOutcome::Status::Ok ? "ok" : "failed";
    j["tetrahedra"] = o.tets;
    j["inner_nodes"] = o.innerNodes;
    j["volume"] = o.volume;
    j["recovery"] = recoveryJson(o.recovery);
    j["quality"] = qualityJson(o.quality);
    nlohmann::ordered_json times = nlohmann::ordered_json::object();
    for (const auto& [phase, sec] : o.times) times[phase] = sec;
    j["times"] = times;
    for (const auto& [name, value] : o.counters) j["stats"][name] = value;
    solids.push_back(j);
  }
  report.extra["solids"] = solids;
}

}  // namespace aniso::app
