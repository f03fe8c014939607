// addFaceMesh — a face's (u, v) triangulation added to the SurfaceMesh: new nodes for the
// interior vertices, triangles (and quads, --quad) on global nodes oriented with the face's normal.
//
// The face mesher works with the boundary normalised to "region on the left" in (u, v),
// i.e. counter-clockwise seen from pu × pv; a reversed face (normal −(pu × pv)) therefore
// gets its triangles flipped. A triangle with two corners on one global node (at a pole,
// where a degenerate edge's boundary nodes all share the vertex node) has no area in 3D
// and is dropped.
#include <sstream>
#include <utility>

#include "mesher/core/Error.h"
#include "mesher/surface/ContourDiscretization.h"

namespace aniso {

void addFaceMesh(const Model& model, int face, const FaceMesh& fm, SurfaceMesh& mesh) {
  const std::string name = "face " + std::to_string(face + 1);
  if (face < 0 || static_cast<std::size_t>(face) >= model.faces.size()) throw MeshingError(name + " does not exist");
  const ModelFace& f = model.faces[face];
  if (!f.surface) throw MeshingError(name + ": no surface");
  if (fm.uv.size() != fm.node.size())
    throw MeshingError(name + ": face mesh has " + std::to_string(fm.uv.size()) + " (u,v) points but " +
                       std::to_string(fm.node.size()) + " node entries");

  std::vector<int> global(fm.uv.size());
  for (std::size_t i = 0; i < fm.uv.size(); ++i) {
    const int g = fm.node[i];
    if (g >= 0) {
      if (static_cast<std::size_t>(g) >= mesh.nodes.size())
        throw MeshingError(name + ": face mesh vertex " + std::to_string(i) + " refers to missing node " + std::to_string(g));
      global[i] = g;
      continue;
    }
    const Vec3 p = f.surface->point(fm.uv[i]);
    if (!p.allFinite() || !fm.uv[i].allFinite()) {
      std::ostringstream s;
      s << name << ": the surface cannot be evaluated at (" << fm.uv[i].x() << ", " << fm.uv[i].y() << ")";
      throw MeshingError(s.str());
    }
    NodeOn on;
    on.kind = NodeOn::Kind::Face;
    on.entity = face;
    on.uv = fm.uv[i];
    global[i] = mesh.addNode(p, on);
  }

  const int nv = static_cast<int>(fm.uv.size());
  for (const std::array<int, 3>& t : fm.triangles) {
    for (int k : t)
      if (k < 0 || k >= nv)
        throw MeshingError(name + ": face mesh triangle refers to vertex " + std::to_string(k) + " of " +
                           std::to_string(nv));
    std::array<int, 3> g{global[t[0]], global[t[1]], global[t[2]]};
    if (g[0] == g[1] || g[1] == g[2] || g[2] == g[0]) continue;
    if (f.reversed) std::swap(g[1], g[2]);
    mesh.triangles.push_back(g);
    mesh.triangleFace.push_back(face);
  }
  // Quads (--quad): one with two corners on one global node (at a pole) is the triangle
  // of its other three; anything more degenerate has no area and is dropped.
  for (const std::array<int, 4>& q : fm.quads) {
    std::array<int, 4> g{};
    for (int k = 0; k < 4; ++k) {
      if (q[k] < 0 || q[k] >= nv)
        throw MeshingError(name + ": face mesh quad refers to vertex " + std::to_string(q[k]) + " of " +
                           std::to_string(nv));
      g[k] = global[q[k]];
    }
    if (f.reversed) std::swap(g[1], g[3]);
    int repeats = 0, at = -1;
    for (int k = 0; k < 4; ++k)
      if (g[k] == g[(k + 1) % 4]) ++repeats, at = k;
    if (repeats == 0 && g[0] != g[2] && g[1] != g[3]) {
      mesh.quads.push_back(g);
      mesh.quadFace.push_back(face);
    } else if (repeats == 1 && g[(at + 2) % 4] != g[(at + 3) % 4]) {
      mesh.triangles.push_back({g[(at + 1) % 4], g[(at + 2) % 4], g[(at + 3) % 4]});
      mesh.triangleFace.push_back(face);
    }
  }
}

}  // namespace aniso
