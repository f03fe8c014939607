#include "tools/app/ModelJson.h"

#include <sstream>

namespace aniso::app {

nlohmann::ordered_json summaryJson(const cad::ShapeSummary& s) {
  nlohmann::ordered_json j;
  j["solids"] = s.solids;
  j["shells"] = s.shells;
  j["faces"] = s.faces;
  j["edges"] = s.edges;
  j["vertices"] = s.vertices;
  j["volume"] = s.volume;
  j["area"] = s.area;
  j["unique_face_area"] = s.uniqueFaceArea;
  j["exposed_area"] = s.exposedArea;
  j["bbox"] = {{"min", {s.bbox.lo.x(), s.bbox.lo.y(), s.bbox.lo.z()}},
               {"max", {s.bbox.hi.x(), s.bbox.hi.y(), s.bbox.hi.z()}},
               {"diagonal", s.bbox.diagonal()}};
  nlohmann::ordered_json list = nlohmann::ordered_json::array();
  for (const auto& so : s.solidList) {
    list.push_back({{"id", so.id}, {"name", so.name}, {"volume", so.volume}});
    if (!so.color.empty()) list.back()["color"] = so.color;
  }
  j["solid_list"] = list;
  return j;
}

nlohmann::ordered_json prepareJson(const cad::PrepareReport& r) {
  nlohmann::ordered_json j;
  j["sewn_faces"] = r.facesSewn;
  j["shared_faces"] = r.sharedFaces;
  j["fuzzy"] = r.fuzzyValue;
  nlohmann::ordered_json ov = nlohmann::ordered_json::array();
  for (const cad::Overlap& o : r.overlaps) {
    nlohmann::ordered_json e{{"a", o.a}, {"b", o.b}, {"name_a", o.nameA}, {"name_b", o.nameB}, {"volume", o.volume}};
    e["assigned_to"] = o.assignedTo > 0 ? nlohmann::ordered_json(o.assignedTo) : nlohmann::ordered_json();
    ov.push_back(e);
  }
  j["overlaps"] = ov;
  j["unfused_solids"] = r.unfusedSolids;
  j["self_overlap_volume"] = r.selfOverlapVolume;
  j["warnings"] = r.warnings;
  return j;
}

std::string summaryText(const cad::ShapeSummary& s, const std::string& in) {
  std::ostringstream o;
  o.precision(10);
  o << in << "solids " << s.solids << ", shells " << s.shells << ", faces " << s.faces << ", edges " << s.edges
    << ", vertices " << s.vertices << "\n";
  o << in << "volume " << s.volume << ", area " << s.area << "\n";
  o << in << "bounding box [" << s.bbox.lo.x() << ", " << s.bbox.lo.y() << ", " << s.bbox.lo.z() << "] - ["
    << s.bbox.hi.x() << ", " << s.bbox.hi.y() << ", " << s.bbox.hi.z() << "], diagonal " << s.bbox.diagonal() << "\n";
  for (const auto& so : s.solidList)
    o << in << "  solid " << so.id << " \"" << so.name << "\" volume " << so.volume
      << (so.color.empty() ? "" : " colour " + so.color) << "\n";
  return o.str();
}

std::string overlapsText(const cad::PrepareReport& r, const std::string& in) {
  std::ostringstream o;
  o.precision(6);
  for (const cad::Overlap& x : r.overlaps) {
    o << in << "solids " << x.a << " \"" << x.nameA << "\" and " << x.b << " \"" << x.nameB << "\" overlap, volume "
      << x.volume;
    if (x.assignedTo > 0) o << ", kept in " << x.assignedTo;
    o << "\n";
  }
  return o.str();
}

}  // namespace aniso::app
