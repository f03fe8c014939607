#pragma once
// Applying a local retriangulation plan (EdgeRemoval.h, or a face flip T23) so that it can
// be undone: the pipe reduction of boundary recovery (thesis 5.4.1) tries a flip, measures
// the pipe, and takes the flip back when it did not help.
#include <array>
#include <vector>

#include "mesher/delaunay3d/FlipT23.h"
#include "mesher/volume/EdgeRemoval.h"

namespace aniso::volume {

struct AppliedChange {
  std::vector<std::array<del3d::VertexId, 4>> newTets;  ///< vertex quadruples created
  std::vector<std::array<del3d::VertexId, 4>> oldTets;  ///< vertex quadruples replaced
};

/// The plan of a face flip T23 in the common form (with its oldQuads).
LocalPlan toPlan(const del3d::TetMesh& mesh, const del3d::Flip23Plan& p);

/// The plan's old tets are alive and still have the vertices recorded when planned.
bool planCurrent(const del3d::TetMesh& mesh, const LocalPlan& plan);

/// Applies the plan (del3d::replaceTets: legality must have been checked).
AppliedChange applyPlan(del3d::TetMesh& mesh, const LocalPlan& plan);

/// Restores the tets replaced by `change`. Later changes must have been undone (the tets
/// of `change` must be in the mesh again, possibly under other ids: they are found by
/// their vertices).
void undoChange(del3d::TetMesh& mesh, const AppliedChange& change);

}  // namespace aniso::volume
