#pragma once
// QuadMesh2d — a mixed triangle/quadrilateral mesh of one face in its parametric plane, the
// working structure of the quad conversion (thesis 4.7–4.8). Index-based (STYLE.md §2–3):
//
//   uv[v], node[v]   vertex position and global SurfaceMesh node (−1: interior vertex);
//   boundary[v]      non-zero for a vertex on the face boundary (never moves, never removed);
//   corners[e]       counter-clockwise in (u, v); corners[e][3] == kNone for a triangle,
//                    corners[e][0] == kNone for a dead (removed) element;
//   adj[e][k]        the element across edge k = (corners[e][k], corners[e][k+1 mod n]),
//                    kNone on the face boundary.
// Elements are never edited in place: an operator removes a patch of elements and adds the
// replacement (replacePatch), so an element id always names one fixed shape. Dead elements
// stay in the arrays until compact().
//
// Built from the face mesher's FaceMesh (boundary vertices first, node ≥ 0 exactly for
// them) and written back to it (triangles and quads, same vertex numbering, new interior
// vertices appended with node −1).
#include <array>
#include <span>
#include <string>
#include <vector>

#include "mesher/core/Types.h"
#include "mesher/surface/FaceBoundary.h"

namespace aniso::quad {

inline constexpr int kNone = -1;
using Corners = std::array<int, 4>;

struct QuadMesh2d {
  std::vector<Vec2> uv;
  std::vector<int> node;
  std::vector<std::uint8_t> boundary;
  std::vector<Corners> corners;
  std::vector<Corners> adj;

  static QuadMesh2d fromFaceMesh(const FaceMesh& fm);
  /// Writes the live elements back (fm.triangles, fm.quads) and the vertices (appended
  /// interior vertices get node −1).
  void toFaceMesh(FaceMesh& fm) const;

  int numVertices() const { return static_cast<int>(uv.size()); }
  int numElements() const { return static_cast<int>(corners.size()); }
  bool alive(int e) const { return corners[e][0] != kNone; }
  /// 3, 4, or 0 for a dead element.
  int sides(int e) const { return corners[e][0] == kNone ? 0 : (corners[e][3] == kNone ? 3 : 4); }
  bool isTriangle(int e) const { return sides(e) == 3; }
  bool isQuad(int e) const { return sides(e) == 4; }
  /// Index k of the directed edge a→b in e (corners k, k+1), or kNone.
  int edgeIndex(int e, int a, int b) const;
  /// Index of vertex v in e, or kNone.
  int cornerIndex(int e, int v) const;

  int addVertex(const Vec2& p);
  /// Undoes the last addVertex (the caller makes sure no element uses it).
  void removeLastVertex() {
    uv.pop_back();
    node.pop_back();
    boundary.pop_back();
  }

  /// Removes the live elements `removed` and adds `added` (counter-clockwise corner lists,
  /// [3] = kNone for triangles); adjacency is rebuilt for the new elements from the links
  /// of the removed ones. The union of `added` must cover exactly the region of `removed`
  /// (same outer edges). Returns the ids of the new elements, in the order given. No
  /// geometric check: callers check legality before calling.
  std::vector<int> replacePatch(std::span<const int> removed, std::span<const Corners> added);

  /// The elements around vertex v, starting at element e (which must contain v), walking
  /// counter-clockwise and then clockwise through the adjacency; `closed` tells whether
  /// the walk came back to e (v interior). Appends to `out` in counter-clockwise order.
  void star(int v, int e, std::vector<int>& out, bool& closed) const;

  /// Drops dead elements (ids change; adjacency remapped).
  void compact();
  /// Drops the inner vertices no live element uses (left by morphing: enclosed vertices,
  /// seams); vertex ids change, the boundary vertices keep theirs (they come first).
  void dropUnusedVertices();

  /// Structural checks, one message per problem: corner indices in range and distinct,
  /// adjacency symmetric with matching (reversed) edges, boundary edges between boundary
  /// vertices. Empty when valid. Geometry is checked by validateGeometry (QuadShape.h).
  std::vector<std::string> validate() const;
};

}  // namespace aniso::quad
