// elevateToOrder2 — mid-edge nodes for surface and volume meshes, then the validity loop
// that leaves straight the elements curving would invert (Order2.h).
#include "mesher/highorder/Order2.h"

#include <algorithm>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>

#include "mesher/core/Error.h"
#include "mesher/surface/MidEdgeGeometry.h"
#include "mesher/highorder/QuadraticJacobian.h"

namespace aniso {
namespace {

/// The mid node of every mesh edge, created on first use; remembers each mid node's chord.
class MidNodes {
 public:
  explicit MidNodes(const SurfaceMesh& mesh) : first_(static_cast<int>(mesh.nodes.size())) {}

  template <class Make>
  int get(SurfaceMesh& mesh, int a, int b, Make&& make) {
    const auto lo = static_cast<std::uint32_t>(std::min(a, b)), hi = static_cast<std::uint32_t>(std::max(a, b));
    const std::uint64_t key = (static_cast<std::uint64_t>(lo) << 32) | hi;
    const auto found = byEdge_.find(key);
    if (found != byEdge_.end()) return found->second;
    const MidNode m = make();
    const int node = mesh.addNode(m.p, m.on);
    byEdge_.emplace(key, node);
    ends_.push_back({a, b});
    return node;
  }

  long long count() const { return static_cast<long long>(ends_.size()); }
  bool isMid(int node) const { return node >= first_ && node - first_ < static_cast<int>(ends_.size()); }
  Vec3 chordMidpoint(const std::vector<Vec3>& nodes, int node) const {
    const auto& e = ends_[node - first_];
    return 0.5 * (nodes[e[0]] + nodes[e[1]]);
  }

 private:
  int first_;
  std::unordered_map<std::uint64_t, int> byEdge_;
  std::vector<std::array<int, 2>> ends_;
};

struct QuadraticElement {
  int corners = 0;  ///< 3 triangle, 4 quad, 4 + isTet tetrahedron
  bool isTet = false;
  std::array<int, 4> corner{};
  std::array<int, 6> mid{};
  int mids() const { return isTet ? 6 : corners; }
};

double jacobianRatio(const QuadraticElement& e, const std::vector<Vec3>& x) {
  if (e.isTet)
    return tet10JacobianRatio({x[e.corner[0]], x[e.corner[1]], x[e.corner[2]], x[e.corner[3]]},
                              {x[e.mid[0]], x[e.mid[1]], x[e.mid[2]], x[e.mid[3]], x[e.mid[4]], x[e.mid[5]]});
  if (e.corners == 3)
    return tri6JacobianRatio({x[e.corner[0]], x[e.corner[1]], x[e.corner[2]]}, {x[e.mid[0]], x[e.mid[1]], x[e.mid[2]]});
  return quad8JacobianRatio({x[e.corner[0]], x[e.corner[1]], x[e.corner[2]], x[e.corner[3]]},
                            {x[e.mid[0]], x[e.mid[1]], x[e.mid[2]], x[e.mid[3]]});
}

/// Puts back at their chord midpoints curved mid nodes of every element whose Jacobian ratio
/// is below kMinJacobianRatio, until none is: the most displaced first, one at a time, until
/// the element passes (so that as many nodes as possible stay on the geometry). Returns the
/// number of elements that needed it.
long long keepValid(std::vector<Vec3>& nodes, const MidNodes& mids, const std::vector<QuadraticElement>& elements) {
  std::vector<char> curved(nodes.size(), 0);
  for (std::size_t i = 0; i < nodes.size(); ++i)
    if (mids.isMid(static_cast<int>(i))) curved[i] = nodes[i] != mids.chordMidpoint(nodes, static_cast<int>(i));
  std::vector<char> straightened(elements.size(), 0);
  long long count = 0;
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t k = 0; k < elements.size(); ++k) {
      const QuadraticElement& e = elements[k];
      bool anyCurved = false;
      for (int i = 0; i < e.mids(); ++i) anyCurved = anyCurved || curved[e.mid[i]];
      if (!anyCurved || jacobianRatio(e, nodes) >= kMinJacobianRatio) continue;
      std::array<std::pair<double, int>, 6> order;
      int n = 0;
      for (int i = 0; i < e.mids(); ++i)
        if (curved[e.mid[i]])
          order[n++] = {-(nodes[e.mid[i]] - mids.chordMidpoint(nodes, e.mid[i])).squaredNorm(), e.mid[i]};
      std::sort(order.begin(), order.begin() + n);  // most displaced first; ties by node: deterministic
      for (int i = 0; i < n; ++i) {
        nodes[order[i].second] = mids.chordMidpoint(nodes, order[i].second);
        curved[order[i].second] = 0;
        if (jacobianRatio(e, nodes) >= kMinJacobianRatio) break;
      }
      if (!straightened[k]) ++count;
      straightened[k] = 1;
      changed = true;
    }
  }
  return count;
}

void checkNodes(const SurfaceMesh& mesh, const int* first, int n, const char* what, std::size_t index) {
  for (int i = 0; i < n; ++i)
    if (first[i] < 0 || static_cast<std::size_t>(first[i]) >= mesh.nodes.size())
      throw MeshingError(std::string("order 2: ") + what + " " + std::to_string(index) + " refers to missing node " +
                         std::to_string(first[i]));
}

/// Creates the surface's mid nodes and returns its elements for the validity loop.
std::vector<QuadraticElement> placeSurfaceMids(const Model& model, SurfaceMesh& mesh, MidNodes& mids) {
  if (!mesh.triangleMid.empty() || !mesh.quadMid.empty()) throw MeshingError("order 2: the mesh is already quadratic");
  if (mesh.nodeOn.size() != mesh.nodes.size() || mesh.triangleFace.size() != mesh.triangles.size() ||
      mesh.quadFace.size() != mesh.quads.size())
    throw MeshingError("order 2: the surface mesh's node or element entities are inconsistent");
  const MidEdgeGeometry geometry(model, mesh);
  std::vector<QuadraticElement> elements;
  mesh.triangleMid.resize(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const std::array<int, 3> tri = mesh.triangles[t];
    checkNodes(mesh, tri.data(), 3, "triangle", t);
    QuadraticElement e{3, false, {tri[0], tri[1], tri[2], -1}, {}};
    for (int k = 0; k < 3; ++k) {
      const int a = tri[k], b = tri[(k + 1) % 3];
      e.mid[k] = mesh.triangleMid[t][k] =
          mids.get(mesh, a, b, [&] { return geometry.place(a, b, mesh.triangleFace[t]); });
    }
    elements.push_back(e);
  }
  mesh.quadMid.resize(mesh.quads.size());
  for (std::size_t q = 0; q < mesh.quads.size(); ++q) {
    const std::array<int, 4> quad = mesh.quads[q];
    checkNodes(mesh, quad.data(), 4, "quad", q);
    QuadraticElement e{4, false, quad, {}};
    for (int k = 0; k < 4; ++k) {
      const int a = quad[k], b = quad[(k + 1) % 4];
      e.mid[k] = mesh.quadMid[q][k] = mids.get(mesh, a, b, [&] { return geometry.place(a, b, mesh.quadFace[q]); });
    }
    elements.push_back(e);
  }
  return elements;
}

}  // namespace

Order2Stats elevateToOrder2(const Model& model, SurfaceMesh& mesh) {
  MidNodes mids(mesh);
  const std::vector<QuadraticElement> elements = placeSurfaceMids(model, mesh, mids);
  Order2Stats stats;
  stats.midNodes = mids.count();
  stats.straightened = keepValid(mesh.nodes, mids, elements);
  return stats;
}

Order2Stats elevateToOrder2(const Model& model, VolumeMesh& mesh) {
  if (!mesh.tetMid.empty()) throw MeshingError("order 2: the mesh is already quadratic");
  if (mesh.tetSolid.size() != mesh.tets.size())
    throw MeshingError("order 2: " + std::to_string(mesh.tets.size()) + " tetrahedra but " +
                       std::to_string(mesh.tetSolid.size()) + " solid entries");
  SurfaceMesh& s = mesh.surface;
  MidNodes mids(s);
  std::vector<QuadraticElement> elements = placeSurfaceMids(model, s, mids);
  mesh.tetMid.resize(mesh.tets.size());
  for (std::size_t t = 0; t < mesh.tets.size(); ++t) {
    const std::array<int, 4> tet = mesh.tets[t];
    checkNodes(s, tet.data(), 4, "tetrahedron", t);
    QuadraticElement e{4, true, tet, {}};
    for (int k = 0; k < 6; ++k) {
      const int a = tet[VolumeMesh::kTetEdges[k][0]], b = tet[VolumeMesh::kTetEdges[k][1]];
      e.mid[k] = mesh.tetMid[t][k] = mids.get(s, a, b, [&] {
        NodeOn on;
        on.kind = NodeOn::Kind::Solid;
        on.entity = mesh.tetSolid[t];
        return MidNode{0.5 * (s.nodes[a] + s.nodes[b]), on};
      });
    }
    elements.push_back(e);
  }
  Order2Stats stats;
  stats.midNodes = mids.count();
  stats.straightened = keepValid(s.nodes, mids, elements);
  return stats;
}

}  // namespace aniso
