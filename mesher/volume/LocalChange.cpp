#include "mesher/volume/LocalChange.h"

#include <algorithm>

#include "mesher/core/Error.h"
#include "mesher/volume/MeshQueries.h"

namespace aniso::volume {

using del3d::TetId;
using del3d::VertexId;

namespace {
std::array<VertexId, 4> quad(const del3d::TetMesh& mesh, TetId t) {
  return {mesh.vertex(t, 0), mesh.vertex(t, 1), mesh.vertex(t, 2), mesh.vertex(t, 3)};
}
}  // namespace

LocalPlan toPlan(const del3d::TetMesh& mesh, const del3d::Flip23Plan& p) {
  LocalPlan out;
  out.oldTets.assign(p.oldTets.begin(), p.oldTets.end());
  out.newTets.assign(p.newTets.begin(), p.newTets.end());
  for (const TetId t : out.oldTets) out.oldQuads.push_back(quad(mesh, t));
  return out;
}

bool planCurrent(const del3d::TetMesh& mesh, const LocalPlan& plan) {
  if (plan.oldQuads.size() != plan.oldTets.size()) return false;
  for (std::size_t k = 0; k < plan.oldTets.size(); ++k)
    if (!mesh.isAlive(plan.oldTets[k]) || quad(mesh, plan.oldTets[k]) != plan.oldQuads[k]) return false;
  return true;
}

AppliedChange applyPlan(del3d::TetMesh& mesh, const LocalPlan& plan) {
  AppliedChange c;
  for (const TetId t : plan.oldTets) c.oldTets.push_back(quad(mesh, t));
  std::vector<TetId> ids(plan.newTets.size());
  del3d::replaceTets(mesh, plan.oldTets, plan.newTets, ids);
  for (const TetId t : ids) c.newTets.push_back(quad(mesh, t));
  return c;
}

void undoChange(del3d::TetMesh& mesh, const AppliedChange& change) {
  std::vector<TetId> current, star;
  for (const auto& q : change.newTets) {
    vertexStar(mesh, q[0], star);
    auto same = [&](TetId t) {
      for (const VertexId v : q)
        if (mesh.localIndex(t, v) < 0) return false;
      return true;
    };
    const auto it = std::find_if(star.begin(), star.end(), same);
    if (it == star.end()) throw MeshingError("undoChange: a tetrahedron of the change is gone");
    current.push_back(*it);
  }
  std::vector<TetId> out(change.oldTets.size());
  del3d::replaceTets(mesh, current, change.oldTets, out);
}

}  // namespace aniso::volume
