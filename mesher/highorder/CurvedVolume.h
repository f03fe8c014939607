#pragma once
// curvedSolidVolumes — the volume each solid's tetrahedra would enclose with their boundary
// triangles bent onto the CAD: the straight volume plus, for every boundary triangle, the
// volume between it and the quadratic triangle through its corners and its mid-edge nodes
// placed as --order 2 places them (surface/MidEdgeGeometry.h). That bulge is A/3 · Σ d_k over the
// three edges, d_k the mid node's offset from the chord midpoint along the triangle's
// outward unit normal (the edge-midpoint rule, exact for a quadratic). It removes the
// chordal deficit of a coarse mesh of curved faces (12 segments per circle: −4.5 % of a
// cylinder's volume) to third order, so the remainder can be compared with the CAD's volume.
#include <vector>

#include "mesher/model/Model.h"
#include "mesher/volume/VolumeMesh.h"

namespace aniso {

/// One value per model solid: the curved volume of the solids flagged in `which` (one flag
/// per solid; empty = all), 0 for the others. A boundary triangle counts for every solid
/// whose tetrahedron it bounds, with that solid's outward orientation. Linear meshes only
/// (tetMid empty); throws MeshingError when a node's NodeOn names an entity out of range.
std::vector<double> curvedSolidVolumes(const Model& model, const VolumeMesh& mesh, const std::vector<char>& which = {});

}  // namespace aniso
