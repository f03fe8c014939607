#pragma once
// SurfaceMesh — the conforming triangle (later also quad) mesh of all faces of a model,
// in 3D: what the writers and the volume mesher consume. Index-based (STYLE.md §2-3).
//
// Nodes are shared: a model vertex has exactly one node; the nodes of a model edge are
// shared by every face using that edge (so meshes are conforming across faces and closed
// on closed shells); interior nodes of a face belong to that face only. Every node records
// the model entity it lies on and its parameters there, so that later stages (quadratic
// elements, projection) can go back to the geometry.
//
// Triangles are oriented with the FACE's normal: counter-clockwise seen from the side the
// face's oriented normal points to (ModelFace::reversed taken into account), so a closed
// shell of consistently oriented faces gives a consistently oriented mesh.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mesher/core/Types.h"

namespace aniso {

struct NodeOn {
  /// Solid: a node inside a solid (volume meshes only), entity = the solid's index.
  enum class Kind : std::uint8_t { Vertex, Edge, Face, Solid } kind = Kind::Face;
  int entity = -1;  ///< 0-based index of the model vertex, edge, face or solid
  double t = 0;     ///< edge nodes: the edge's curve parameter
  Vec2 uv{0, 0};    ///< face nodes: parameters on that face
};

struct SurfaceMesh {
  std::vector<Vec3> nodes;
  std::vector<NodeOn> nodeOn;
  std::vector<std::array<int, 3>> triangles;
  std::vector<int> triangleFace;  ///< 0-based model face of each triangle
  /// Quadrilaterals (quad-dominant meshes, thesis 4.7–4.8): corners counter-clockwise seen
  /// from the face's oriented normal, like the triangles. Empty for triangle meshes.
  std::vector<std::array<int, 4>> quads;
  std::vector<int> quadFace;  ///< 0-based model face of each quad

  /// Quadratic elements (--order 2), empty for linear meshes. The mid-edge nodes are
  /// ordinary nodes (appended to `nodes`, with the NodeOn of the entity they were projected
  /// on). triangleMid[t][k] is the node on edge (k, k+1 mod 3) of triangles[t];
  /// quadMid[q][k] the node on edge (k, k+1 mod 4) of quads[q] (8-node serendipity quads).
  /// Writers permute to their format's node order.
  std::vector<std::array<int, 3>> triangleMid;
  std::vector<std::array<int, 4>> quadMid;

  int addNode(const Vec3& p, const NodeOn& on) {
    nodes.push_back(p);
    nodeOn.push_back(on);
    return static_cast<int>(nodes.size()) - 1;
  }

  /// Structural checks, one message per problem: indices in range, no triangle with a
  /// repeated node, no two triangles with the same three nodes, no edge used by more than
  /// two triangles of the same face. Empty when valid.
  std::vector<std::string> validate() const;

  struct EdgeCounts {
    long long open = 0;         ///< mesh edges used by one triangle
    long long nonManifold = 0;  ///< used by more than two
    long long misoriented = 0;  ///< used twice in the same direction
  };
  EdgeCounts edgeCounts() const;
};

}  // namespace aniso
