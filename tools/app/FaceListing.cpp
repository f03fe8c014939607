#include "tools/app/FaceListing.h"

#include <cmath>
#include <cstdio>

namespace aniso::app {
namespace {

using json = nlohmann::ordered_json;

json entryJson(const cad::CatalogEntry& e, const char* measure, bool edge) {
  json j;
  j["id"] = e.id;
  j["type"] = e.type;
  j[measure] = e.measure;
  j["centroid"] = {e.centroid.x(), e.centroid.y(), e.centroid.z()};
  j["bbox"] = {{"min", {e.bbox.lo.x(), e.bbox.lo.y(), e.bbox.lo.z()}},
               {"max", {e.bbox.hi.x(), e.bbox.hi.y(), e.bbox.hi.z()}}};
  if (edge) j["faces"] = e.faces;
  j["solids"] = e.solids;
  j["part"] = e.part;
  if (!e.name.empty()) j["name"] = e.name;
  if (!e.color.empty()) j["color"] = e.color;
  return j;
}

std::string ids(const std::vector<int>& v) {
  std::string s;
  for (const int i : v) {
    if (!s.empty()) s += ',';
    s += std::to_string(i);
  }
  return s.empty() ? "-" : s;
}

/// A coordinate for the table: values below kPrintZero of the entry's box diagonal print
/// as 0 (a centroid on a symmetry plane, -9.9e-32 otherwise).
constexpr double kPrintZero = 1e-12;

std::string line(const cad::CatalogEntry& e, const std::vector<int>& neighbours) {
  const double zero = kPrintZero * (e.bbox.empty() ? 1.0 : e.bbox.diagonal());
  const auto snap = [zero](double v) { return std::abs(v) < zero ? 0.0 : v; };
  char buf[512];
  std::snprintf(buf, sizeof buf, "%6d  %-11s %12.6g  %10.6g %10.6g %10.6g  %-8s %s", e.id, e.type.c_str(),
                e.measure, snap(e.centroid.x()), snap(e.centroid.y()), snap(e.centroid.z()), ids(neighbours).c_str(),
                e.part.empty() ? "-" : e.part.c_str());
  std::string s = buf;
  if (!e.name.empty()) s += "  name \"" + e.name + "\"";
  if (!e.color.empty()) s += "  colour " + e.color;
  return s + "\n";
}

}  // namespace

json catalogJson(const cad::FaceCatalog& c) {
  json faces = json::array(), edges = json::array();
  for (const cad::CatalogEntry& e : c.faces) faces.push_back(entryJson(e, "area", false));
  for (const cad::CatalogEntry& e : c.edges) edges.push_back(entryJson(e, "length", true));
  return {{"face_list", faces}, {"edge_list", edges}};
}

std::string catalogText(const cad::FaceCatalog& c) {
  std::string s = "faces (the mesh's FACE<n> groups):\n    id  type                area    centroid x          y          z  solids   part\n";
  for (const cad::CatalogEntry& e : c.faces) s += line(e, e.solids);
  s += "edges (EDGE<n>):\n    id  type              length    centroid x          y          z  faces    part\n";
  for (const cad::CatalogEntry& e : c.edges) s += line(e, e.faces);
  return s;
}

}  // namespace aniso::app
