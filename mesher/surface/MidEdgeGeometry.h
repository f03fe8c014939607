#pragma once
// MidEdgeGeometry — where the mid node of a surface mesh edge goes: on the model edge's
// curve when the edge runs along a model edge, else on the face's surface (the rules are in
// highorder/Order2.h). Reads the model and the mesh's nodes and NodeOn; the mesh may grow between
// calls (nodes are read through the reference).
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "mesher/model/Model.h"
#include "mesher/surface/SurfaceMesh.h"

namespace aniso {

struct MidNode {
  Vec3 p;
  NodeOn on;
};

class MidEdgeGeometry {
 public:
  /// Indexes the model edges' discretizations found in the mesh (vertex nodes and edge
  /// nodes sorted by t). Throws MeshingError when a NodeOn names an entity out of range.
  MidEdgeGeometry(const Model& model, const SurfaceMesh& mesh);

  /// The mid node of mesh edge (a, b) of an element on model face `face`.
  MidNode place(int a, int b, int face) const;

 private:
  struct Link {
    int edge = -1;
    double ta = 0, tb = 0;  ///< parameters of the lower and the higher node index
  };
  struct UvCandidate {
    Vec2 uv{0, 0};
    const PCurve* pole = nullptr;  ///< a degenerate edge's pcurve: any point on it is the node
  };

  MidNode onCurve(int a, int b, const Link& link) const;
  MidNode onSurface(int a, int b, int face) const;
  std::vector<UvCandidate> uvCandidates(int node, int face) const;
  /// The (u, v) of both ends, representatives nearest each other. False when none is known.
  bool closestUvPair(int a, int b, int face, Vec2& ua, Vec2& ub) const;

  const Model& model_;
  const SurfaceMesh& mesh_;
  std::unordered_map<std::uint64_t, Link> links_;  ///< mesh edges along model edges
  std::vector<std::vector<int>> vertexEdges_;      ///< model edges at each model vertex
};

}  // namespace aniso
