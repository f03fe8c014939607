#include "mesher/delaunay3d/Delaunay3d.h"

#include <memory>
#include <numeric>

#include "mesher/core/Error.h"
#include "mesher/core/Log.h"
#include "mesher/delaunay3d/Inserter.h"
#include "mesher/delaunay3d/RemoveTets.h"
#include "mesher/delaunay3d/SeedOctree.h"
#include "mesher/delaunay3d/SpatialSort.h"

namespace aniso::del3d {

DelaunayResult buildDelaunay(TetMesh& mesh, std::span<const Vec3> points, const DelaunayOptions& options) {
  mesh.clear();
  DelaunayResult res;
  res.vertexOf.assign(points.size(), VertexId());
  Box3 bounds;
  for (const Vec3& p : points)
    if (p.allFinite()) bounds.add(p);
  if (bounds.empty()) throw MeshingError("buildDelaunay: no finite point");
  if (options.reserve) mesh.reserve(points.size() + 8, points.size() * 7 + 64);
  const Mat3* m = options.transform.isIdentity(0.0) ? nullptr : &options.transform;
  res.box = createEnclosingBox(mesh, bounds, options.boxMargin, m);

  std::vector<std::uint32_t> order;
  if (options.spatialSort) {
    order = brioOrder(points, options.sortSeed);
  } else {
    order.resize(points.size());
    std::iota(order.begin(), order.end(), 0u);
  }
  std::unique_ptr<SeedOctree> octree;
  if (options.useSeedOctree) {
    octree = std::make_unique<SeedOctree>(res.box.box, options.octreeLeafThreshold);
    for (std::uint32_t k = 0; k < mesh.tetSlots(); ++k) octree->update(mesh, TetId(k));
  }
  Inserter inserter(mesh);
  // With the identity the cached circumspheres decide most in-sphere tests without the
  // exact predicate's filter (the same decisions: Circumsphere.h).
  if (!m) inserter.cacheSpheres();
  Progress progress("Delaunay 3D", static_cast<double>(points.size()));
  std::size_t done = 0;
  for (const std::uint32_t k : order) {
    if ((++done & 0xFFFu) == 0) progress.update(static_cast<double>(done));
    const Vec3& p = points[k];
    if (!p.allFinite()) {
      ++res.nonFinite;
      continue;
    }
    const TetId start = octree ? octree->seed(mesh, p) : TetId();
    const InsertResult r = inserter.insert(p, start, m);
    switch (r.status) {
      case InsertStatus::Inserted:
        ++res.inserted;
        res.vertexOf[k] = r.vertex;
        if (octree)
          for (const TetId t : inserter.newTets()) octree->update(mesh, t);
        break;
      case InsertStatus::Duplicate:
        ++res.duplicates;
        res.vertexOf[k] = r.vertex;
        break;
      case InsertStatus::Outside:  // cannot happen inside the enclosing box
      case InsertStatus::Refused:
      case InsertStatus::Pointless:  // not asked for
        ++res.refused;
        break;
    }
  }
  if (options.removeBox) {
    const std::vector<TetId> boxTets = tetsTouching(mesh, res.box.corners);
    removeTets(mesh, boxTets);
  }
  return res;
}

}  // namespace aniso::del3d
