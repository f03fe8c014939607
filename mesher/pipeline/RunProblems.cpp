#include "mesher/pipeline/RunProblems.h"

#include <algorithm>
#include <set>
#include <tuple>

namespace aniso {

std::vector<std::string> facePartNames(const Model& m) {
  std::vector<std::string> out(m.faces.size());
  for (std::size_t s = 0; s < m.solids.size(); ++s)
    for (const int f : m.solidFaces(static_cast<int>(s)))
      if (f >= 0 && static_cast<std::size_t>(f) < out.size() && out[static_cast<std::size_t>(f)].empty())
        out[static_cast<std::size_t>(f)] = m.solids[s].name;
  return out;
}

ModelGrade gradeModel(const Model& topo) {
  const std::vector<std::string> parts = facePartNames(topo);
  ModelGrade g;
  g.skipFaces.assign(topo.faces.size(), 0);
  // the detail drops the place in the loop: two junctions of a loop can say the same
  std::set<std::tuple<EntityKind, int, std::string>> seen;
  for (const ModelIssue& i : topo.check()) {
    // the message names its entity; the problem's detail is the rest of it
    const std::size_t colon = i.message.find(": ");
    const std::string detail = colon == std::string::npos ? i.message : i.message.substr(colon + 2);
    EntityRef ref{i.kind, i.index + 1, {}};
    if (i.kind == EntityKind::Face) ref.part = parts[static_cast<std::size_t>(i.index)];
    Problem p{ref, Severity::Note, "cad-defect", detail, "model"};
    if (i.level == ModelIssue::Level::Gap) {
      p.severity = Severity::Degraded;
      p.code = "loop-gap";
      p.detail += "; meshed across the gap";
    } else if (i.level == ModelIssue::Level::Unusable) {
      p.severity = Severity::Failed;
      p.code = "cad-unusable";
      if (i.kind == EntityKind::Face) g.skipFaces[static_cast<std::size_t>(i.index)] = 1;
      else if (i.kind == EntityKind::Edge)
        for (const int f : topo.edges[static_cast<std::size_t>(i.index)].faces)
          g.skipFaces[static_cast<std::size_t>(f)] = 1;
      else g.usable = false;
    }
    if (seen.insert({ref.kind, ref.id, p.code + p.detail}).second) g.problems.push_back(std::move(p));
  }
  if (std::all_of(g.skipFaces.begin(), g.skipFaces.end(), [](char c) { return c != 0; })) g.usable = false;
  return g;
}

std::vector<Problem> surfaceProblems(const Model& model, const SurfaceMeshResult& sr) {
  const std::vector<std::string> parts = facePartNames(model);
  std::vector<Problem> out;
  for (std::size_t f = 0; f < sr.faces.size(); ++f) {
    const std::vector<std::string>& ps = sr.faces[f].problems;
    if (ps.empty()) continue;
    std::string detail = "not meshed: " + ps.front();
    if (ps.size() > 1) detail += " (and " + std::to_string(ps.size() - 1) + " more)";
    out.push_back({EntityRef::face(static_cast<int>(f), parts[f]), Severity::Failed, "face-mesh", detail, "surface"});
  }
  // refinement stopped at its insertion bound (FaceMesher.h): valid, coarser than asked somewhere
  for (std::size_t f = 0; f < sr.faces.size(); ++f)
    if (sr.faces[f].problems.empty() && sr.faces[f].stats.insertionLimitReached)
      out.push_back({EntityRef::face(static_cast<int>(f), parts[f]), Severity::Note, "refinement-limit",
                     "its refinement stopped at the insertion bound: elements may be larger than the sizing asks "
                     "somewhere",
                     "surface"});
  // faces meshed, then collapsed by the surface repair (SurfaceSlivers.h: narrower than its
  // tolerance): the surface stays closed over them, but a load or support on them has no nodes
  std::vector<int> left(sr.faces.size(), 0);
  for (const int f : sr.mesh.triangleFace)
    if (f >= 0 && static_cast<std::size_t>(f) < left.size()) ++left[static_cast<std::size_t>(f)];
  for (const int f : sr.mesh.quadFace)
    if (f >= 0 && static_cast<std::size_t>(f) < left.size()) ++left[static_cast<std::size_t>(f)];
  for (std::size_t f = 0; f < sr.faces.size(); ++f) {
    const FaceOutcome& o = sr.faces[f];
    if (o.problems.empty() && o.sharedWith < 0 && o.triangles + o.quads > 0 && left[f] == 0)
      out.push_back({EntityRef::face(static_cast<int>(f), parts[f]), Severity::Note, "face-collapsed",
                     "narrower than the surface tolerance: merged into its neighbours, it has no elements", "surface"});
  }
  return out;
}

std::vector<Problem> volumeProblems(const Model& model, const VolumeMeshResult& vr) {
  std::vector<Problem> out;
  for (const SolidOutcome& o : vr.solids)
    for (Problem p : o.problems) {
      if (p.entity.kind == EntityKind::Solid && p.entity.part.empty() && p.entity.id >= 1 &&
          static_cast<std::size_t>(p.entity.id) <= model.solids.size())
        p.entity.part = model.solids[static_cast<std::size_t>(p.entity.id - 1)].name;
      out.push_back(std::move(p));
    }
  return out;
}

}  // namespace aniso
