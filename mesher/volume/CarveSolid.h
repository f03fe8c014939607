#pragma once
// Removal of the exterior, void and box tetrahedra once the boundary is recovered (thesis
// sec. 5.4: "elements adjacent to boundary facets are identified as belonging to meshed
// domain or not. After constraining this information is spread to other elements
// (through adjacent elements but not crossing the boundary faces). Finally, the unmarked
// tetrahedra are removed").
//
// Components of tets connected across non-constrained faces (and across the embedded
// faces' triangles, which have the solid on both sides) are classified by one
// constrained face each: inside when the tet's vertex opposite that face lies on the inner
// side of the outward boundary triangle (exact orient3d < 0). A component touching the
// hull or the box corners is outside. Every constrained face of a component must agree;
// disagreements are reported (they mean a face is missing or misoriented).
#include <string>
#include <vector>

#include "mesher/delaunay3d/EnclosingBox.h"
#include "mesher/volume/BoundaryTriangulation.h"
#include "mesher/volume/SolidTetMesh.h"

namespace aniso {

/// Marks every boundary and embedded triangle constrained (it must be present), removes every tet
/// outside the solid. Returns problems (empty on success); on problems nothing is removed.
std::vector<std::string> carveSolid(SolidTetMesh& s, const SolidBoundary& boundary, const del3d::EnclosingBox& box);

}  // namespace aniso
