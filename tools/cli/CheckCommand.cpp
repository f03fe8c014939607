// anisomesh check MESH: read a mesh in any supported format and report counts, surface
// topology, validity and quality (io/readers/MeshCheck.h); exit 0 valid, 3 invalid,
// 2 unreadable (InputError from the reader).
#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "io/readers/MeshCheck.h"
#include "tools/cli/Commands.h"

namespace aniso::cli {
namespace {

nlohmann::ordered_json counts(const std::vector<std::pair<std::string, long long>>& c) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const auto& [name, n] : c) j[name] = n;
  return j;
}

nlohmann::ordered_json histogramJson(const io::QualityHistogram& h) {
  return {{"count", h.count}, {"min", h.min}, {"avg", h.average()}, {"max", h.max},
          {"range", {h.lo, h.hi}}, {"histogram", h.bins}};
}

nlohmann::ordered_json toJson(const std::string& file, const io::MeshCheckReport& r) {
  nlohmann::ordered_json j;
  j["file"] = file;
  j["format"] = r.format;
  j["valid"] = r.valid();
  j["problems"] = r.problems;
  j["nodes"] = r.nodes;
  j["elements"] = counts(r.elements);
  nlohmann::ordered_json groups = nlohmann::ordered_json::array();
  for (const auto& g : r.groups) groups.push_back({{"name", g.name}, {"elements", counts(g.elements)}});
  j["groups"] = groups;
  if (!r.nodeSets.empty()) j["node_sets"] = counts(r.nodeSets);
  j["surface"] = {{"of", r.volume ? "volume boundary" : "surface elements"}, {"faces", r.surfaceFaces},
                  {"closed", r.closed()}, {"manifold", r.manifold()}, {"oriented", r.oriented()},
                  {"open_edges", r.openEdges}, {"non_manifold_edges", r.nonManifoldEdges},
                  {"misoriented_edges", r.misorientedEdges}, {"non_manifold_faces", r.nonManifoldFaces}};
  j["inverted"] = r.inverted;
  j["degenerate"] = r.degenerate;
  if (r.unchecked) j["unchecked_3d_elements"] = r.unchecked;
  nlohmann::ordered_json q = nlohmann::ordered_json::object();
  if (r.triangleMeanRatio.count) q["triangle_mean_ratio"] = histogramJson(r.triangleMeanRatio);
  if (r.quadScaledJacobian.count) q["quad_scaled_jacobian"] = histogramJson(r.quadScaledJacobian);
  if (r.tetMeanRatio.count) q["tet_mean_ratio"] = histogramJson(r.tetMeanRatio);
  if (r.tetDihedral.count) q["tet_dihedral_deg"] = histogramJson(r.tetDihedral);
  j["quality"] = q;
  return j;
}

std::string countLine(const std::vector<std::pair<std::string, long long>>& c) {
  std::ostringstream s;
  for (const auto& [name, n] : c) s << "  " << name << " " << n;
  return s.str();
}

void printHistogram(const char* what, const io::QualityHistogram& h) {
  if (!h.count) return;
  std::printf("  %-22s min %.4g  avg %.4g  max %.4g\n   ", what, h.min, h.average(), h.max);
  const double step = (h.hi - h.lo) / static_cast<double>(h.bins.size());
  for (std::size_t b = 0; b < h.bins.size(); ++b) std::printf(" %g:%lld", h.lo + step * static_cast<double>(b), h.bins[b]);
  std::printf("\n");
}

void printText(const std::string& file, const io::MeshCheckReport& r) {
  long long elements = 0;
  for (const auto& e : r.elements) elements += e.second;
  std::printf("%s: %s, %lld nodes, %lld elements\n", file.c_str(), r.format.c_str(), r.nodes, elements);
  std::printf("elements:%s\n", countLine(r.elements).c_str());
  if (!r.groups.empty()) std::printf("groups:\n");
  for (const auto& g : r.groups) std::printf("  %-24s%s\n", g.name.c_str(), countLine(g.elements).c_str());
  if (!r.nodeSets.empty()) std::printf("node sets:%s\n", countLine(r.nodeSets).c_str());
  std::printf("surface (%s): %lld faces, %s, %s, %s\n", r.volume ? "boundary of the volume mesh" : "surface elements",
              r.surfaceFaces, r.closed() ? "closed" : ("open (" + std::to_string(r.openEdges) + " edges)").c_str(),
              r.manifold() ? "manifold" : "non-manifold", r.oriented() ? "consistently oriented" : "misoriented");
  if (r.nonManifoldEdges || r.misorientedEdges || r.nonManifoldFaces)
    std::printf("  non-manifold edges %lld, misoriented edges %lld, faces of more than two tetrahedra %lld\n",
                r.nonManifoldEdges, r.misorientedEdges, r.nonManifoldFaces);
  std::printf("inverted elements: %lld, degenerate: %lld\n", r.inverted, r.degenerate);
  if (r.unchecked) std::printf("3D elements other than tetrahedra (not checked): %lld\n", r.unchecked);
  std::printf("quality:\n");
  printHistogram("triangle mean ratio", r.triangleMeanRatio);
  printHistogram("quad scaled Jacobian", r.quadScaledJacobian);
  printHistogram("tet mean ratio", r.tetMeanRatio);
  printHistogram("tet dihedral (deg)", r.tetDihedral);
  if (r.valid()) {
    std::printf("valid\n");
  } else {
    std::printf("INVALID:\n");
    for (const std::string& p : r.problems) std::printf("  %s\n", p.c_str());
  }
}

}  // namespace

int runCheck(const CheckArgs& args) {
  const io::MeshCheckReport r = io::checkMesh(io::readMesh(args.file));
  if (args.json) {
    std::printf("%s\n", toJson(args.file, r).dump().c_str());
  } else {
    printText(args.file, r);
  }
  return r.valid() ? 0 : 3;
}

}  // namespace aniso::cli
