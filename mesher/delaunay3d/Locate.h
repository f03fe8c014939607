#pragma once
// Point location by a visibility walk (thesis sec. 5.3.2): starting from a tetrahedron
// (the last one created, or a seed from SeedOctree), step to the neighbour across a face
// that separates the current tetrahedron from the point, decided exactly by orient3d on
// the untransformed coordinates. The walk is the "remembering stochastic walk" of
// Devillers, Pion & Teillaud (2002): the faces are tried from a random first index and
// the face just crossed is never re-tested, which breaks the cycles a deterministic
// visibility walk can fall into. A step budget guards non-Delaunay meshes; past it the
// location falls back to an exact scan of all tetrahedra, so the answer is always right.
#include <cstdint>

#include "mesher/delaunay3d/TetMesh.h"

namespace aniso::del3d {

enum class LocateStatus {
  Inside,    ///< strictly inside `tet`
  OnFace,    ///< on one face of `tet` (zeroFaces has one bit)
  OnEdge,    ///< on an edge of `tet` (zeroFaces has two bits)
  OnVertex,  ///< equal to vertex `vertex` of `tet`
  Outside,   ///< the walk left the mesh through a hull face of `tet` (`face`)
};

struct LocateResult {
  LocateStatus status = LocateStatus::Outside;
  TetId tet;                 ///< containing tet (closed), or the last tet before leaving
  int face = -1;             ///< Outside: hull face of `tet` the point lies beyond
  unsigned zeroFaces = 0;    ///< bit i set: the point lies on the plane of face i of `tet`
  VertexId vertex;           ///< OnVertex: the coinciding vertex
  std::uint32_t steps = 0;   ///< tetrahedra visited
};

/// Locates p starting at `start` (must be a live tet). `rng` is the caller's random state
/// (any nonzero value; advanced in place). The mesh must be valid (positive tets, symmetric
/// adjacency). With the convex enclosing box of EnclosingBox.h, Outside means p is outside
/// the box; after removeTets() the hull may be non-convex and Outside only means that the
/// straight walk left the mesh.
LocateResult locate(const TetMesh& mesh, const double p[3], TetId start, std::uint32_t& rng);

}  // namespace aniso::del3d
