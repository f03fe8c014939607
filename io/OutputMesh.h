#pragma once
// OutputMesh — what every writer reads: a surface mesh, or a volume mesh with its surface,
// seen as one list of nodes and three element kinds (triangles, quads, tetrahedra), each
// linear or quadratic. Element nodes come in our canonical order: the corners, then the
// mid-edge nodes in the data contracts' edge order (SurfaceMesh::triangleMid / quadMid,
// VolumeMesh::kTetEdges); io/ElementOrder.h permutes them to each format's order.
#include <algorithm>
#include <array>
#include <string>
#include <vector>

#include "mesher/model/Model.h"
#include "mesher/surface/SurfaceMesh.h"
#include "mesher/volume/VolumeMesh.h"

namespace aniso::io {

enum class Shape { Triangle, Quad, Tet };

struct OutputMesh {
  const Model& model;
  const SurfaceMesh& surface;             ///< all nodes; the boundary (face) elements
  const VolumeMesh* volume = nullptr;     ///< null for a surface mesh

  OutputMesh(const Model& m, const SurfaceMesh& s) : model(m), surface(s) {}
  OutputMesh(const Model& m, const VolumeMesh& v) : model(m), surface(v.surface), volume(&v) {}

  bool isVolume() const { return volume != nullptr; }
  const std::vector<Vec3>& nodes() const { return surface.nodes; }
  int count(Shape s) const;
  bool quadratic(Shape s) const;
  /// Nodes per element of this shape: 3/6, 4/8, 4/10.
  int nodesPer(Shape s) const;
  /// The element's nodes (0-based) in canonical order; returns their number.
  int elementNodes(Shape s, int i, std::array<int, 10>& out) const;
  /// 0-based model face of a triangle or quad, solid of a tetrahedron.
  int entityOf(Shape s, int i) const;

  /// Elements of a shape grouped by entity (face for triangles/quads, solid for tets),
  /// each list in increasing element index.
  std::vector<std::vector<int>> byEntity(Shape s) const;
  /// Faces (0-based) that hold at least one triangle or quad.
  std::vector<bool> meshedFaces() const;
  /// Solids (0-based) that hold at least one tetrahedron (none for a surface mesh).
  std::vector<bool> meshedSolids() const;
  /// Throws MeshingError naming `path` if the mesh's arrays are inconsistent (an element
  /// pointing outside the nodes, an entity outside the model, missing mid-edge arrays).
  void check(const std::string& path) const;
};

/// The CAD faces that share one STEP face name (ModelFace::name): one group of the output.
struct FaceGroup {
  std::string name;        ///< the group's name (see groupNames)
  std::vector<int> faces;  ///< 0-based, ascending
};

/// The names every writer gives its groups, the same in every format (MSH, INP, VTU, UNV):
///  - `solids`: one per solid, its part name ("SOLID<n>" without one);
///  - `faces`: one per distinct STEP face name, in the order of its first face (named faces
///    are grouped beside their FACE<n> groups; a model without face names has none).
/// Every name is made a valid Abaqus/CalculiX identifier, since INP needs one: letters,
/// digits and '_' (any other character, also non-ASCII bytes, becomes '_'), starting with a
/// letter ("P_" put before one that does not), at most 64 characters ("l-bracket" becomes
/// "l_bracket", "load face" "load_face"). Names are then made unique across solids and face
/// groups together, compared case-insensitively as CalculiX does, by a suffix "_2", "_3"
/// (solids first, so a part keeps its name), and never equal a name the writers define
/// themselves (NALL, EALL, FACE<n>, S_FACE<n>, EDGE<n>).
struct GroupNames {
  std::vector<std::string> solids;
  std::vector<FaceGroup> faces;
};
GroupNames groupNames(const Model& model);

/// The ids of a face group: the concatenation of perFace[f] over group.faces, sorted and
/// without repeats (node and element ids of a named face group in the INP and UNV writers).
template <class T>
std::vector<T> groupIds(const FaceGroup& group, const std::vector<std::vector<T>>& perFace) {
  std::vector<T> ids;
  for (const int f : group.faces) ids.insert(ids.end(), perFace[f].begin(), perFace[f].end());
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

/// Mean ratio of a triangle in 3D (1 equilateral, 0 degenerate), of a tetrahedron
/// (negative when inverted), scaled Jacobian of a quad (min over the corners of the
/// normalized corner Jacobian against the quad's mean normal). Corners only.
double elementQuality(const OutputMesh& mesh, Shape s, int i);

}  // namespace aniso::io
