#pragma once
// Point location in a Triangulation2d (thesis sec. 4.4.1, Fig. 4.6(a)): a directed walk
// from a starting triangle towards the point, the start taken from the seeding quadtree
// (SeedQuadtree.h) unless the caller gives one.
//
// Walk: visibility walk with exact orient2d — from triangle t, cross an edge whose line
// has the point strictly on its far side; the first edge tested is chosen at random and
// the edge just crossed is not re-tested (remembering stochastic walk, Devillers, Pion &
// Teillaud 2002), which terminates on any valid triangulation with probability 1. As a
// guard against pathological cycling, after max(1000, 2·#triangles) steps the walk falls
// back to testing every live triangle (exact, linear time).
//
// Limitation: the walk reports Outside as soon as it must cross a boundary edge. That is
// exact while the triangulated region is convex (the box triangulation before domain
// removal); after triangles have been removed (DomainMarking.h) a point inside a
// non-convex region may be reported Outside when the straight walk leaves the region.
#include <cstddef>

#include "mesher/core/Types.h"
#include "mesher/delaunay/Triangulation2d.h"

namespace aniso::del2d {

enum class Location {
  Inside,    ///< strictly inside `tri`
  OnEdge,    ///< on edge `index` of `tri` (strictly between its endpoints)
  OnVertex,  ///< equal to vertex `index` of `tri`
  Outside,   ///< outside the triangulation; `tri` is the last triangle visited
};

struct LocateResult {
  TriId tri;
  Location where = Location::Outside;
  int index = -1;
  std::size_t steps = 0;  ///< triangles visited (statistics)
};

/// A starting triangle for a walk towards p: the triangle of the nearest sampled vertex
/// of the seeding quadtree, else the last created triangle, else any live triangle;
/// invalid only when the triangulation has no triangle.
TriId seedTriangle(const Triangulation2d& tri, const Vec2& p);

/// Locates p (finite) by walking from `start` (a live triangle; invalid → seedTriangle).
/// Uses the triangulation's workspace for the random choices (not thread-safe per object).
LocateResult locate(const Triangulation2d& tri, const Vec2& p, TriId start = TriId());

}  // namespace aniso::del2d
