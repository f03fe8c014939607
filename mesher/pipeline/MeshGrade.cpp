#include "mesher/pipeline/MeshGrade.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>
#include <string>

#include "mesher/highorder/CurvedVolume.h"
#include "mesher/pipeline/RunProblems.h"
#include "mesher/volume/TetQuality.h"
#include "mesher/metric/MeanRatio.h"

namespace aniso {
namespace {

std::string format(const char* fmt, double a, double b = 0, double c = 0) {
  char buf[256];
  std::snprintf(buf, sizeof buf, fmt, a, b, c);
  return buf;
}

EntityRef solidRef(const Model& model, std::size_t s) { return EntityRef::solid(static_cast<int>(s), model.solids[s].name); }

/// The CAD faces a node lies on: its face, the faces of its edge, or of the edges at its vertex.
void facesOfNode(const Model& model, const NodeOn& on, std::set<int>& out) {
  const auto in = [](int i, std::size_t n) { return i >= 0 && static_cast<std::size_t>(i) < n; };
  if (on.kind == NodeOn::Kind::Face && in(on.entity, model.faces.size())) out.insert(on.entity);
  if (on.kind == NodeOn::Kind::Edge && in(on.entity, model.edges.size()))
    out.insert(model.edges[static_cast<std::size_t>(on.entity)].faces.begin(),
               model.edges[static_cast<std::size_t>(on.entity)].faces.end());
  if (on.kind == NodeOn::Kind::Vertex)
    for (const ModelEdge& e : model.edges)
      if (e.v0 == on.entity || e.v1 == on.entity) out.insert(e.faces.begin(), e.faces.end());
}

/// The flattest tetrahedron (referee's dihedral) of each solid flagged in `which`, in one
/// pass over the mesh; tets.size() for a solid with none.
std::vector<std::size_t> flattestTets(const VolumeMesh& mesh, const std::vector<char>& which) {
  const std::vector<Vec3>& x = mesh.nodes();
  std::vector<std::size_t> at(which.size(), mesh.tets.size());
  std::vector<double> worst(which.size(), 180);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const auto s = static_cast<std::size_t>(mesh.tetSolid[t]);
    if (s >= which.size() || !which[s]) continue;
    const auto& k = mesh.tets[t];
    if (const double d = refereeMinDihedral(x[k[0]], x[k[1]], x[k[2]], x[k[3]]); d < worst[s]) {
      worst[s] = d;
      at[s] = t;
    }
  }
  return at;
}

/// Where tetrahedron t is and the CAD faces its nodes lie on: ", the flattest at (x, y, z)
/// by faces 12, 43" (the faces whose surface mesh forces it, when the sliver cannot be
/// removed without changing the surface).
std::string whereSliver(const Model& model, const VolumeMesh& mesh, std::size_t t) {
  if (t >= mesh.tets.size()) return "";
  const std::vector<Vec3>& x = mesh.nodes();
  const auto& k = mesh.tets[t];
  const Vec3 c = 0.25 * (x[k[0]] + x[k[1]] + x[k[2]] + x[k[3]]);
  std::set<int> faces;
  for (const int n : k)
    if (static_cast<std::size_t>(n) < mesh.surface.nodeOn.size()) facesOfNode(model, mesh.surface.nodeOn[n], faces);
  std::string where = format(", the flattest at (%.6g, %.6g, %.6g)", c.x(), c.y(), c.z());
  if (faces.empty()) return where + ", inside the solid";
  where += faces.size() > 1 ? " by faces " : " by face ";
  int shown = 0;
  for (const int f : faces) {
    if (shown++ == 4) {
      where += ", ...";
      break;
    }
    where += (shown > 1 ? ", " : "") + std::to_string(f + 1);
  }
  return where;
}

/// Thickness of solid s as a plate would have it: twice its volume over its boundary's area
/// (the CAD's); 0 when not known.
double plateThickness(const Model& model, std::size_t s) {
  const ModelSolid& solid = model.solids[s];
  double area = 0;
  const auto add = [&](int shell) {
    if (shell >= 0 && static_cast<std::size_t>(shell) < model.shells.size())
      for (const FaceUse& u : model.shells[static_cast<std::size_t>(shell)].faces)
        if (u.face >= 0 && static_cast<std::size_t>(u.face) < model.faces.size())
          area += model.faces[static_cast<std::size_t>(u.face)].cadArea;
  };
  add(solid.outerShell);
  for (const int v : solid.voidShells) add(v);
  return area > 0 && solid.cadVolume > 0 ? 2 * solid.cadVolume / area : 0;
}

/// Which solids pull the mean ratio below the bar: ", mostly solid 31 'label' (65 k tets,
/// mean 0.23, about 0.001 thick), ...; the other tetrahedra average 0.83". The solids below the bar
/// by their shortfall (tets times the mean's distance to the bar), at most kShown of them;
/// "" when no solid is below the bar.
std::string lowQualityCause(const Model& model, const VolumeMeshResult& volume) {
  constexpr std::size_t kShown = 3;
  const std::size_t n = std::min(model.solids.size(), volume.solids.size());
  std::vector<std::pair<double, std::size_t>> shortfall;
  for (std::size_t s = 0; s < n; ++s) {
    const QualityStats& q = volume.solids[s].quality.meanRatio;
    if (q.count() > 0 && q.mean() < kMeanRatioBar)
      shortfall.push_back({static_cast<double>(q.count()) * (kMeanRatioBar - q.mean()), s});
  }
  if (shortfall.empty()) return "";
  std::sort(shortfall.begin(), shortfall.end(), [](const auto& a, const auto& b) {
    return a.first != b.first ? a.first > b.first : a.second < b.second;
  });
  std::string why = ", mostly";
  const QualityStats& all = volume.quality.meanRatio;
  double sum = all.mean() * static_cast<double>(all.count()), count = static_cast<double>(all.count());
  for (std::size_t i = 0; i < shortfall.size() && i < kShown; ++i) {
    const std::size_t s = shortfall[i].second;
    const QualityStats& q = volume.solids[s].quality.meanRatio;
    why += (i ? ", " : " ") + std::string("solid ") + std::to_string(s + 1) + " '" + model.solids[s].name + "'" +
           format(" (%.0f tets, mean %.2f", static_cast<double>(q.count()), q.mean());
    if (const double t = plateThickness(model, s); t > 0) why += format(", about %.2g thick", t);
    why += ")";
    sum -= q.mean() * static_cast<double>(q.count());
    count -= static_cast<double>(q.count());
  }
  if (shortfall.size() > kShown) why += format(" and %.0f more below the bar", static_cast<double>(shortfall.size() - kShown));
  if (count > 0) why += format("; the other tetrahedra average %.3f", sum / count);
  return why;
}

}  // namespace

std::vector<Problem> gradeSurfaceGeometry(const Model& model, const SurfaceGeometryCheck& check) {
  std::vector<Problem> out;
  const std::vector<std::string> parts = facePartNames(model);
  const auto part = [&](int f) { return f >= 0 && static_cast<std::size_t>(f) < parts.size() ? parts[f] : std::string(); };
  for (const auto& [f, n] : check.foldedFaces)
    out.push_back({EntityRef::face(f, part(f)), Severity::Degraded, "surface-fold",
                   format("its surface mesh folds over at %.0f edges (neighbouring triangles more than 84 deg apart)", n),
                   "surface"});
  for (const auto& [f, n] : check.flatFaces)
    out.push_back({EntityRef::face(f, part(f)), Severity::Degraded, "flat-triangles",
                   format("%.0f of its triangles are flat (no area a solver can use)", n), "surface"});
  for (const auto& [f, n] : check.crossingFaces)
    out.push_back({EntityRef::face(f, part(f)), Severity::Degraded, "surface-crossing",
                   format("its triangles cross a neighbouring face's near their common edge (%.0f pairs "
                          "of triangles cross)",
                          n),
                   "surface"});
  for (const auto& [s, n] : check.openSolids)
    out.push_back({solidRef(model, static_cast<std::size_t>(s)), Severity::Degraded, "surface-open",
                   format("its boundary mesh is open at %.0f edges", static_cast<double>(n)), "surface"});
  return out;
}

std::vector<Problem> gradeVolumeMesh(const Model& model, const VolumeMeshResult& volume, bool isotropic) {
  std::vector<Problem> out;
  const std::size_t n = std::min(model.solids.size(), volume.solids.size());
  std::vector<char> mismatched(model.solids.size(), 0), slivers(model.solids.size(), 0);
  bool anyMismatch = false, anySliver = false;
  const auto meshed = [&](std::size_t s) {
    return volume.solids[s].status == SolidOutcome::Status::Ok && volume.solids[s].tets > 0;
  };
  for (std::size_t s = 0; s < n; ++s)
    if (meshed(s) && volume.solids[s].quality.refereeMinDihedral < kSliverBarDeg) slivers[s] = anySliver = true;
  const std::vector<std::size_t> flattest = anySliver ? flattestTets(volume.mesh, slivers) : std::vector<std::size_t>();
  for (std::size_t s = 0; s < n; ++s) {
    const SolidOutcome& o = volume.solids[s];
    if (!meshed(s)) continue;
    if (slivers[s])
      out.push_back({solidRef(model, s), Severity::Degraded, "slivers",
                     format("its smallest dihedral angle is %.2f deg (bar: %.0f deg), tetrahedra below 5 deg: %.0f",
                            o.quality.refereeMinDihedral, kSliverBarDeg, static_cast<double>(o.quality.belowDihedral)) +
                         whereSliver(model, volume.mesh, flattest[s]),
                     "quality"});
    if (o.quality.inverted > 0)  // positive in exact arithmetic, not in the double sum a reader computes
      out.push_back({solidRef(model, s), Severity::Degraded, "flat-tetrahedra",
                     format("%.0f tetrahedra have a volume that is zero or negative when computed in floating point",
                            static_cast<double>(o.quality.inverted)),
                     "quality"});
    const double cad = model.solids[s].cadVolume;
    if (cad > 0 && std::abs(o.volume - cad) > kVolumeMismatchRel * cad) {
      mismatched[s] = 1;
      anyMismatch = true;
    }
  }
  if (anyMismatch) {  // the straight volume misses the chordal bulge: check the curved one
    const std::vector<double> curved = curvedSolidVolumes(model, volume.mesh, mismatched);
    for (std::size_t s = 0; s < n; ++s) {
      if (!mismatched[s]) continue;
      const double cad = model.solids[s].cadVolume, rel = (curved[s] - cad) / cad;
      if (std::abs(rel) <= kVolumeMismatchRel) continue;
      out.push_back({solidRef(model, s), Severity::Degraded, "volume-mismatch",
                     format("its mesh encloses %.6g, the CAD solid %.6g (%+.1f %%): a face may be missing, or the CAD "
                            "solid intersects itself or states a wrong volume",
                            curved[s], cad, 100 * rel),
                     "quality"});
    }
  }
  const QualityStats& eta = volume.quality.meanRatio;
  if (isotropic && eta.count() > 0 && eta.mean() < kMeanRatioBar)
    out.push_back({EntityRef::model(), Severity::Degraded, "low-quality",
                   format("the tetrahedra's mean ratio averages %.3f (bar: %.2f)", eta.mean(), kMeanRatioBar) +
                       lowQualityCause(model, volume),
                   "quality"});
  return out;
}

std::vector<Problem> gradeSurfaceMesh(const SurfaceMesh& mesh, bool isotropic) {
  if (!isotropic || mesh.triangles.empty() || !mesh.quads.empty()) return {};
  double sum = 0;
  for (const auto& t : mesh.triangles)
    sum += meanRatio(mesh.nodes[static_cast<std::size_t>(t[0])], mesh.nodes[static_cast<std::size_t>(t[1])],
                     mesh.nodes[static_cast<std::size_t>(t[2])]);
  const double mean = sum / static_cast<double>(mesh.triangles.size());
  if (mean >= kTriangleMeanRatioBar) return {};
  return {{EntityRef::model(), Severity::Degraded, "low-quality",
           format("the triangles' mean ratio averages %.3f (bar: %.2f)", mean, kTriangleMeanRatioBar), "quality"}};
}

}  // namespace aniso
