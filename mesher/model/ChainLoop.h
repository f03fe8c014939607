#pragma once
// chainLoopUses — a face loop's edge uses put in walking order by their vertices and
// pcurves, for a wire OpenCASCADE's explorer cannot walk (cad/TopologyBuilder.cpp; KiCad's
// beaded test points: a surface of revolution periodic both ways, its four edges stored out
// of walking order).
#include <vector>

#include "mesher/model/Model.h"

namespace aniso {

/// Reorders `uses` (non-empty, each with its pcurve on the face) from the first so that each
/// ends at the vertex the next starts from, at the (u, v) nearest to it among the uses
/// starting there (two closed edges at one vertex: the profile circles of a half torus);
/// leaves `uses` unchanged when no such order exists.
void chainLoopUses(const Model& model, std::vector<EdgeUse>& uses);

}  // namespace aniso
