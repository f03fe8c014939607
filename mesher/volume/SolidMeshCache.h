#pragma once
// SolidMeshCache — the finished tetrahedra of each solid, kept between the calls of
// meshVolumes of one run (the proximity rounds of alg. 3.3, the final volume, the
// coarse-solid retry: mesher/pipeline/VolumeStages.cpp). Those calls mesh a surface in which
// most solids' boundaries are unchanged; such a solid's tetrahedra are taken from the cache
// instead of being made again.
//
// A solid's entry is keyed by its boundary as meshSolid sees it: the triangles of its
// shells' and embedded faces (face by face, ascending face and triangle index), each node
// by its rank among the solid's nodes sorted by surface index, its coordinates and its
// NodeOn (kind, entity, t, uv), all bit for bit, hashed into 128 bits. Equal keys mean the
// same input to meshSolid up to a renumbering of the surface nodes that keeps their order,
// so the stored tetrahedra (their surface nodes kept as ranks) are the ones meshSolid would
// make again: the output does not depend on the cache (tests/unit/solid_mesh_cache_test.cpp
// meshes with and without it).
// Valid only across calls with the same model, options, user sizing and recovery options.
// Only complete pieces with no problems are stored. find and store for distinct solids may
// run concurrently.
#include <array>
#include <cstdint>
#include <optional>
#include <vector>

#include "mesher/model/Model.h"
#include "mesher/surface/SurfaceMesh.h"
#include "mesher/volume/SolidPiece.h"

namespace aniso {

/// A solid's boundary as meshSolid sees it: the key and the solid's surface nodes in
/// ascending index (rank -> surface node).
struct SolidBoundaryKey {
  std::array<std::uint64_t, 2> hash{0, 0};
  std::size_t triangles = 0;
  std::vector<int> nodes;
  bool operator==(const SolidBoundaryKey& o) const { return hash == o.hash && triangles == o.triangles && nodes.size() == o.nodes.size(); }
};

/// faceTriangles: trianglesByFace(surface, model.faces.size()).
SolidBoundaryKey solidBoundaryKey(const Model& model, const SurfaceMesh& surface,
                                  const std::vector<std::vector<int>>& faceTriangles, int solid);

class SolidMeshCache {
 public:
  explicit SolidMeshCache(std::size_t solids) : entries_(solids) {}
  /// The solid's piece, its tetrahedra renumbered to key.nodes, when the stored key equals
  /// `key`; the entry stays.
  std::optional<SolidPiece> find(int solid, const SolidBoundaryKey& key) const;
  /// Keeps a complete, problem-free piece (its surface node ids taken as ranks in key.nodes);
  /// anything else clears the solid's entry.
  void store(int solid, const SolidBoundaryKey& key, const SolidPiece& piece);

 private:
  struct Entry {
    SolidBoundaryKey key;
    SolidPiece piece;  ///< tets' fixed vertices as ranks
    bool valid = false;
  };
  std::vector<Entry> entries_;
};

}  // namespace aniso
