#pragma once
// Carving when boundary recovery left some boundary triangles out (the last resort of
// VolumeMesher, after the split rounds stopped): the solid is kept with a mesh whose hull
// differs from its boundary triangles in a few places ("holes"), rather than left without
// tetrahedra.
//
// carveSolid (CarveSolid.h) classifies whole components between constrained faces; a
// missing triangle joins the inside and the outside into one component. Here each tet is
// classified instead: the tets on a present boundary triangle take its side (exact
// orient3d), the tets on the hull or the enclosing box are outside, the others take the
// side of their centroid against the whole boundary, missing triangles included (the
// parity of a ray, RayParity.h), and the few whose every ray is degenerate the side of the
// nearest classified tet (breadth-first across unconstrained faces, in tet slot order).
// Deterministic. Groups of inside tets on no present boundary triangle are outside.
//
// After removing the outside tets:
//  - a present triangle that no longer separates inside from outside is counted missing
//    too and its constrained bit cleared;
//  - the hull faces that are no boundary triangle ("patch faces", closing each hole) get
//    the constrained bit, and their vertices are pinned (SolidTetMesh::pinned), so the
//    later phases treat them as boundary: never moved, flipped or removed.
// The caller compares `keptVolume` with `enclosedVolume` before accepting the result.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mesher/delaunay3d/EnclosingBox.h"
#include "mesher/volume/BoundaryTriangulation.h"
#include "mesher/volume/SolidTetMesh.h"

namespace aniso {

/// A carving around holes is accepted when the tets kept enclose the volume of the solid's
/// boundary triangles within this share of it (the patches stand where a few triangles
/// are missing: far less; more means the fronts met in the wrong place). 1 %, the bar a
/// volume mesh is judged by against its CAD solid: a surface that still folds over after the
/// repair encloses its own volume only roughly, and carving it loses a fraction of a percent
/// (docs/measurements.md).
inline constexpr double kHoleVolumeTolerance = 1e-2;

struct HoleCarving {
  std::vector<std::size_t> missing;  ///< boundary triangles (SolidBoundary index) not on the hull
  std::size_t notFound = 0;          ///< of them, those recovery left out (the others: lost by the fronts)
  std::size_t patchFaces = 0;        ///< hull faces that are no boundary triangle
  double missingArea = 0;            ///< of the missing triangles
  double patchArea = 0;              ///< of the patch faces
  double enclosedVolume = 0;         ///< by the solid's boundary triangles (all of them)
  double keptVolume = 0;             ///< of the tets kept
  std::vector<std::string> problems; ///< empty on success; on problems nothing is removed
};

/// Classifies and removes the tets outside the solid as above. Embedded triangles must all
/// be present (a problem otherwise).
HoleCarving carveAroundHoles(SolidTetMesh& s, const SolidBoundary& boundary, const del3d::EnclosingBox& box);

/// Tets flatter than this (smallest dihedral angle, degrees) on a patch face are peeled
/// off once the solid is improved: a patch face is made of whatever nodes the holes
/// had, often nearly collinear, and no vertex of it may move.
inline constexpr double kPatchSliverAngle = 3.0;
/// ... and those whose mean ratio is below this (angles of no meaning: vertices a few
/// units in the last place apart, which recovery's Steiner points can be).
inline constexpr double kPatchFlatRatio = 0.01;

/// Removes the tets on a patch face whose smallest dihedral angle is below `angle` (or mean
/// ratio below kPatchFlatRatio), again
/// and again as peeling exposes new patch faces (constrained, their vertices pinned, in
/// s.patchFaces), while the volume removed stays within `maxVolume`. A tet with a face on
/// a boundary triangle too is removed all the same (a flat tet along the surface): that
/// triangle joins the holes (the caller finds which: hull faces no longer). Returns the
/// number of tets removed.
std::size_t peelPatchSlivers(SolidTetMesh& s, double angle, double maxVolume);

}  // namespace aniso
