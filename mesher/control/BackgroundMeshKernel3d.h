#pragma once
// BackgroundMeshKernel<3> — the tetrahedron kernel of BackgroundMesh3d (interface:
// BackgroundMeshKernel.h): a del3d::TetMesh built by the kernel's Inserter (Bowyer–Watson,
// identity metric) inside createEnclosingBox of the bounds; its 8 corners are vertices
// 0..7.
//
// Location: del3d::locate (visibility walk on the caller's random state) from `start`
// (when live) or else from a tetrahedron of the nearest vertex in a VertexSeedOctree
// (BackgroundMeshSeeds.h), which every insertion updates at once (settle() has nothing
// left to do). On a face or an edge the tetrahedron with the smallest slot is returned,
// so the answer depends on p only.
#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "mesher/control/BackgroundMeshKernel.h"
#include "mesher/control/BackgroundMeshOptions.h"
#include "mesher/control/BackgroundMeshSeeds.h"
#include "mesher/delaunay3d/Inserter.h"
#include "mesher/delaunay3d/TetMesh.h"

namespace aniso {

template <>
class BackgroundMeshKernel<3> {
 public:
  using Elem = del3d::TetId;
  static constexpr int kCorners = 4;
  static constexpr int kEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  static constexpr const char* kElementName = "tetrahedron";

  /// The enclosing box of `bounds` (margin options.boxMargin), its corners in the seed
  /// octree.
  BackgroundMeshKernel(const Box3& bounds, const BackgroundMeshOptions& options);

  const del3d::TetMesh& tetMesh() const { return *mesh_; }
  std::size_t numVertices() const { return mesh_->numVertices(); }
  Vec3 point(std::uint32_t v) const { return mesh_->point(del3d::VertexId(v)); }
  const double* coords(std::uint32_t v) const { return mesh_->coords(del3d::VertexId(v)); }
  std::size_t elementCount() const { return mesh_->numTets(); }
  std::size_t slots() const { return mesh_->tetSlots(); }
  bool isAlive(Elem t) const { return mesh_->isAlive(t); }
  const std::uint32_t* vertices(Elem t) const { return mesh_->tetVertices(t); }
  Elem neighbour(Elem t, int i) const { return mesh_->neighbour(t, i); }
  Elem vertexElement(std::uint32_t v) const { return mesh_->vertexTet(del3d::VertexId(v)); }

  Elem locate(const Vec3& p, Elem start, std::uint32_t& rng) const;
  KernelInsertion insert(const Vec3& p, Elem near);
  /// The Inserter's new tetrahedra of the last insertion.
  void appendCreated(int v, std::vector<Elem>& out) const;
  /// Breadth-first through the faces incident to v.
  void appendStar(int v, std::vector<Elem>& out) const;
  /// The six edges of every live tetrahedron (shared edges repeated).
  std::vector<std::array<int, 2>> edgePairs() const;

  Vec3 centroid(Elem t) const;
  bool closureContains(Elem t, const Vec3& x) const;
  Vec3 circumcentre(Elem t) const;
  bool inSphere(Elem t, const Vec3& p) const;
  double maxEdgeLength(Elem t, const Mat3& m) const;
  std::vector<std::string> validate() const;
  void settle() const {}

 private:
  std::unique_ptr<del3d::TetMesh> mesh_;  ///< heap: the Inserter keeps a reference
  std::unique_ptr<del3d::Inserter> inserter_;
  std::unique_ptr<VertexSeedOctree> seeds_;
};

}  // namespace aniso
