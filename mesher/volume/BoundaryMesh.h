#pragma once
// BoundaryMesh — the closed triangulated boundary of ONE solid (thesis sec. 5.3, step 1:
// "the triangular discretizations of all surface patches defining each volume block have
// to be projected into 3D space and combined into a consistent boundary description").
//
// Taken from the SurfaceMesh (which is already in 3D, nodes shared across faces): the
// triangles of every face of the solid's outer shell and void shells, ORIENTED OUTWARD
// from the solid (counter-clockwise seen from outside the material; for a void shell the
// normals point into the void). The orientation is decided by the shell's face uses
// (FaceUse::reversed against ModelFace::reversed, the surface mesh following the latter)
// and checked per shell with the signed volume (positive for the outer shell, negative
// for a void shell); a shell whose sign comes out wrong as a whole is flipped (an OCCT
// shell stored reversed). A face used twice by the solid with opposite orientations lies
// inside the material (both sides are the solid): its triangles are left out (its nodes
// stay, as fixed interior nodes); with the same orientation it is taken once. Likewise two
// triangles of different faces on the same three nodes with opposite orientations (two
// coincident faces sharing one mesh, surface/contour/CoincidentFaces.h: a slit left by a
// boolean) are both left out, and a face left with no triangle counts as internal.
//
// The triangles of the solid's embedded faces (ModelSolid::embedded) are kept apart: they
// lie inside the material and are not part of the closed boundary.
//
// checkBoundaryMesh validates, BEFORE any 3D work, that the result is closed and
// consistently oriented: every undirected edge is used by as many triangles in one
// direction as in the other, and at least once each way (two in a manifold boundary, four
// at an edge where the solid touches itself). A failure is a bug of the surface mesh: the
// messages name the CAD faces (1-based ids) around the bad edges.
#include <array>
#include <string>
#include <vector>

#include "mesher/model/Model.h"
#include "mesher/surface/SurfaceMesh.h"

namespace aniso {

struct BoundaryMesh {
  int solid = -1;                               ///< 0-based model solid
  std::vector<std::array<int, 3>> triangles;    ///< surface-mesh node triples, outward
  std::vector<int> triangleFace;                ///< 0-based model face of each triangle
  std::vector<int> nodes;                       ///< every surface node of the solid's faces (embedded too), sorted
  std::vector<int> faces;                       ///< 0-based faces whose triangles are kept, sorted
  std::vector<int> flippedShells;               ///< shells whose face uses gave the inward side
  std::vector<int> internalFaces;               ///< faces left out (used twice, opposite ways)
  /// Triangles of the solid's embedded faces (ModelSolid::embedded; surface-mesh orientation,
  /// which has no inside/outside meaning here): constraints inside the solid, not boundary.
  std::vector<std::array<int, 3>> embedded;
  std::vector<int> embeddedFace;                ///< 0-based model face of each embedded triangle
};

/// Triangles of each face of `mesh`: faceTriangles[f] lists the indices into
/// mesh.triangles of face f (built once, shared by all solids).
std::vector<std::vector<int>> trianglesByFace(const SurfaceMesh& mesh, int numFaces);

/// The outward boundary mesh of solid `solid` (0-based). Does not validate: call
/// checkBoundaryMesh. Throws InputError for an out-of-range solid or shell.
BoundaryMesh buildBoundaryMesh(const Model& model, const SurfaceMesh& mesh,
                               const std::vector<std::vector<int>>& faceTriangles, int solid);

/// Closedness and orientation (see above); one message per kind of problem, naming the
/// solid and the faces (1-based). Empty when valid.
std::vector<std::string> checkBoundaryMesh(const BoundaryMesh& b, const SurfaceMesh& mesh);

/// Signed volume enclosed by the triangles (divergence theorem, about the first node):
/// positive for an outward-oriented closed surface.
double signedVolume(const SurfaceMesh& mesh, const std::vector<std::array<int, 3>>& triangles);

}  // namespace aniso
