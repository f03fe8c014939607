#pragma once
// BackgroundMeshKernel<2> — the triangle kernel of BackgroundMesh2d (interface:
// BackgroundMeshKernel.h): a del2d::Triangulation2d built and updated by the meshing
// kernel itself in the identity metric, over the kernel's enlarged box of the bounds
// (its four corners are vertices 0..3).
//
// Location: from `start` (when live) or else from a triangle of the nearest vertex in the
// kernel's seeding quadtree (sec. 3.4.5: "an additional quadtree … for selection of good
// starting element"; leaves of 8 vertices here), a remembering stochastic visibility walk
// with exact orient2d on the caller's random state; when p lies on an edge the triangle
// with the smaller slot is returned, so the answer depends on p only. The kernel's own
// walk (PointLocation.h) draws its random choices from the triangulation's workspace and
// its seeding quadtree is filled lazily: hence the walk of its own here, and settle(),
// which fills the quadtree after every modification.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mesher/control/BackgroundMeshKernel.h"
#include "mesher/control/BackgroundMeshOptions.h"
#include "mesher/delaunay/Triangulation2d.h"

namespace aniso {

template <>
class BackgroundMeshKernel<2> {
 public:
  using Elem = del2d::TriId;
  static constexpr int kCorners = 3;
  /// Edge i is the one opposite vertex i.
  static constexpr int kEdges[3][2] = {{1, 2}, {2, 0}, {0, 1}};
  static constexpr const char* kElementName = "triangle";

  /// The triangulation of the box of `bounds` enlarged by options.boxMargin, its seeding
  /// quadtree filled.
  BackgroundMeshKernel(const Box2& bounds, const BackgroundMeshOptions& options);

  const del2d::Triangulation2d& triangulation() const { return tri_; }
  std::size_t numVertices() const { return tri_.numVertices(); }
  const Vec2& point(std::uint32_t v) const { return tri_.point(del2d::VertexId(v)); }
  const double* coords(std::uint32_t v) const { return tri_.coords(del2d::VertexId(v)); }
  std::size_t elementCount() const { return tri_.numTriangles(); }
  std::size_t slots() const { return tri_.triangleSlots(); }
  bool isAlive(Elem t) const { return tri_.isAlive(t); }
  const std::uint32_t* vertices(Elem t) const { return tri_.triVertices(t); }
  Elem neighbour(Elem t, int i) const { return tri_.neighbour(t, i); }
  Elem vertexElement(std::uint32_t v) const { return tri_.vertexTriangle(del2d::VertexId(v)); }

  Elem locate(const Vec2& p, Elem start, std::uint32_t& rng) const;
  KernelInsertion insert(const Vec2& p, Elem near);
  /// The star of a new vertex is what its insertion created.
  void appendCreated(int v, std::vector<Elem>& out) const { appendStar(v, out); }
  /// Rotates around v one way until back at the start, or both ways on the boundary.
  void appendStar(int v, std::vector<Elem>& out) const;
  /// Every edge once, from the triangle with the smaller slot (or the only one).
  std::vector<std::array<int, 2>> edgePairs() const;

  Vec2 centroid(Elem t) const;
  bool closureContains(Elem t, const Vec2& x) const;
  Vec2 circumcentre(Elem t) const;
  bool inSphere(Elem t, const Vec2& p) const;
  /// max over the edges of |M e|.
  double maxEdgeLength(Elem t, const Mat2& m) const;
  std::vector<std::string> validate() const;
  void settle() const { tri_.seeds(); }

 private:
  /// Walk to a triangle whose closure contains p; `zeros` gets bit i when p is on the
  /// line of edge i.
  Elem walk(const Vec2& p, Elem start, std::uint32_t& rng, unsigned& zeros) const;

  del2d::Triangulation2d tri_;
};

}  // namespace aniso
