// checkMesh (MeshCheck.h): counts, surface topology, validity and quality of a read mesh.
#include "io/readers/MeshCheck.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "mesher/highorder/QuadraticJacobian.h"
#include "mesher/metric/MeanRatio.h"

namespace aniso::io {
namespace {

/// A triangle or tetrahedron whose area or volume, relative to the cube (square) of its
/// root-mean-square edge length, is below this is degenerate: zero up to round-off, its
/// orientation (and a quadratic element's Jacobian sign) meaningless.
constexpr double kDegenerateSize = 1e-12;

bool degenerateTriangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double l2 = ((b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm()) / 3;
  return !((b - a).cross(c - a).norm() > kDegenerateSize * l2);
}

bool degenerateTet(const std::array<Vec3, 4>& p) {
  double l2 = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) l2 += (p[j] - p[i]).squaredNorm() / 6;
  const double v = std::abs((p[1] - p[0]).dot((p[2] - p[0]).cross(p[3] - p[0])));
  return !(v > kDegenerateSize * l2 * std::sqrt(l2));
}

/// Outward faces of a positively oriented tetrahedron (p1−p0)·((p2−p0)×(p3−p0)) > 0.
constexpr int kTetFaces[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

double triangleMeanRatio(const Vec3& a, const Vec3& b, const Vec3& c) {
  const double sum = (b - a).squaredNorm() + (c - b).squaredNorm() + (a - c).squaredNorm();
  return sum > 0 ? 2 * std::sqrt(3.0) * (b - a).cross(c - a).norm() / sum : 0.0;
}

/// Minimum over the corners of the normalized corner Jacobian against the quad's normal
/// (from its diagonals): 1 for a square, ≤ 0 for a non-convex or folded quad.
double quadScaledJacobian(const std::array<Vec3, 4>& p) {
  const Vec3 n = (p[2] - p[0]).cross(p[3] - p[1]);
  if (!(n.norm() > 0)) return 0;
  const Vec3 unit = n.normalized();
  double worst = 1;
  for (int i = 0; i < 4; ++i) {
    const Vec3 e1 = p[(i + 1) % 4] - p[i], e2 = p[(i + 3) % 4] - p[i];
    const double l = e1.norm() * e2.norm();
    worst = std::min(worst, l > 0 ? unit.dot(e1.cross(e2)) / l : 0.0);
  }
  return worst;
}

/// The six dihedral angles of a tetrahedron, in degrees.
std::array<double, 6> dihedralAngles(const std::array<Vec3, 4>& p) {
  static constexpr int edges[6][4] = {{0, 1, 2, 3}, {1, 2, 0, 3}, {2, 0, 1, 3}, {0, 3, 1, 2}, {1, 3, 0, 2}, {2, 3, 0, 1}};
  std::array<double, 6> out{};
  for (int k = 0; k < 6; ++k) {
    const Vec3& a = p[edges[k][0]];
    const Vec3 e = (p[edges[k][1]] - a).normalized();
    Vec3 u = p[edges[k][2]] - a, v = p[edges[k][3]] - a;
    u -= u.dot(e) * e;
    v -= v.dot(e) * e;
    const double c = u.norm() * v.norm() > 0 ? u.dot(v) / (u.norm() * v.norm()) : 1.0;
    out[k] = std::acos(std::clamp(c, -1.0, 1.0)) * 180 / std::numbers::pi;
  }
  return out;
}

struct EdgeUse {
  int a, b;  ///< a < b
  bool forward;
  bool operator<(const EdgeUse& o) const { return a != o.a ? a < o.a : b != o.b ? b < o.b : forward < o.forward; }
};

/// Edge topology of a set of oriented polygons (node lists).
void countEdges(const std::vector<std::vector<int>>& faces, MeshCheckReport& r) {
  std::vector<EdgeUse> uses;
  for (const std::vector<int>& f : faces)
    for (std::size_t k = 0; k < f.size(); ++k) {
      const int p = f[k], q = f[(k + 1) % f.size()];
      uses.push_back({std::min(p, q), std::max(p, q), p < q});
    }
  std::sort(uses.begin(), uses.end());
  for (std::size_t i = 0; i < uses.size();) {
    std::size_t j = i;
    while (j < uses.size() && uses[j].a == uses[i].a && uses[j].b == uses[i].b) ++j;
    const std::size_t n = j - i;
    if (n == 1) ++r.openEdges;
    if (n > 2) ++r.nonManifoldEdges;
    if (n == 2 && uses[i].forward == uses[i + 1].forward) ++r.misorientedEdges;
    i = j;
  }
  r.surfaceFaces = static_cast<long long>(faces.size());
}

/// The faces used by exactly one tetrahedron, outward; counts faces used by more than two.
std::vector<std::vector<int>> tetBoundary(const ReadMesh& m, MeshCheckReport& r) {
  struct Face {
    std::array<int, 3> key, oriented;
    bool operator<(const Face& o) const { return key < o.key; }
  };
  std::vector<Face> faces;
  for (std::size_t i = 0; i < m.cellCount(); ++i) {
    if (m.types[i] != CellType::Tet && m.types[i] != CellType::Tet10) continue;
    const int* c = m.cell(i);
    for (const auto& f : kTetFaces) {
      Face face{{c[f[0]], c[f[1]], c[f[2]]}, {c[f[0]], c[f[1]], c[f[2]]}};
      std::sort(face.key.begin(), face.key.end());
      faces.push_back(face);
    }
  }
  std::sort(faces.begin(), faces.end());
  std::vector<std::vector<int>> boundary;
  for (std::size_t i = 0; i < faces.size();) {
    std::size_t j = i;
    while (j < faces.size() && faces[j].key == faces[i].key) ++j;
    if (j - i == 1) boundary.push_back({faces[i].oriented[0], faces[i].oriented[1], faces[i].oriented[2]});
    if (j - i > 2) ++r.nonManifoldFaces;
    i = j;
  }
  return boundary;
}

/// Validity and quality of one element; its corner polygon for the surface of a surface mesh.
void measure(const ReadMesh& m, std::size_t i, MeshCheckReport& r, std::vector<std::vector<int>>& polygons) {
  const int* c = m.cell(i);
  const auto& x = m.nodes;
  switch (m.types[i]) {
    case CellType::Triangle:
    case CellType::Triangle6: {
      const double q = triangleMeanRatio(x[c[0]], x[c[1]], x[c[2]]);
      r.triangleMeanRatio.add(q);
      if (degenerateTriangle(x[c[0]], x[c[1]], x[c[2]])) ++r.degenerate;
      else if (m.types[i] == CellType::Triangle6 &&
               tri6JacobianRatio({x[c[0]], x[c[1]], x[c[2]]}, {x[c[3]], x[c[4]], x[c[5]]}) <= 0)
        ++r.inverted;
      polygons.push_back({c[0], c[1], c[2]});
      break;
    }
    case CellType::Quad:
    case CellType::Quad8:
    case CellType::Quad9: {
      const std::array<Vec3, 4> p = {x[c[0]], x[c[1]], x[c[2]], x[c[3]]};
      const double q = quadScaledJacobian(p);
      r.quadScaledJacobian.add(q);
      if (q <= 0) ++r.inverted;
      else if (m.types[i] != CellType::Quad && quad8JacobianRatio(p, {x[c[4]], x[c[5]], x[c[6]], x[c[7]]}) <= 0)
        ++r.inverted;
      polygons.push_back({c[0], c[1], c[2], c[3]});
      break;
    }
    case CellType::Polygon:
      polygons.emplace_back(c, c + m.cellSize(i));
      break;
    case CellType::Tet:
    case CellType::Tet10: {
      const std::array<Vec3, 4> p = {x[c[0]], x[c[1]], x[c[2]], x[c[3]]};
      const double q = meanRatio(p[0], p[1], p[2], p[3]);
      r.tetMeanRatio.add(q);
      for (double a : dihedralAngles(p)) r.tetDihedral.add(a);
      if (degenerateTet(p)) ++r.degenerate;
      else if (q <= 0) ++r.inverted;
      else if (m.types[i] == CellType::Tet10 &&
               tet10JacobianRatio(p, {x[c[4]], x[c[5]], x[c[6]], x[c[7]], x[c[8]], x[c[9]]}) <= 0)
        ++r.inverted;
      break;
    }
    default:
      if (cellDimension(m.types[i]) == 3) ++r.unchecked;
      break;
  }
}

std::vector<std::pair<std::string, long long>> countTypes(const ReadMesh& m, const std::vector<int>* cells) {
  std::vector<long long> n(static_cast<int>(CellType::Polygon) + 1, 0);
  if (cells) {
    for (int i : cells[0]) ++n[static_cast<int>(m.types[i])];
  } else {
    for (CellType t : m.types) ++n[static_cast<int>(t)];
  }
  std::vector<std::pair<std::string, long long>> out;
  for (std::size_t t = 0; t < n.size(); ++t)
    if (n[t]) out.emplace_back(cellTypeName(static_cast<CellType>(t)), n[t]);
  return out;
}

void listProblems(MeshCheckReport& r) {
  auto add = [&](long long n, const std::string& what) {
    if (n) r.problems.push_back(std::to_string(n) + " " + what);
  };
  add(r.inverted, "inverted elements (non-positive Jacobian)");
  add(r.degenerate, "degenerate elements (zero area or volume)");
  if (r.volume) {
    add(r.nonManifoldFaces, "faces shared by more than two tetrahedra");
    add(r.openEdges, "open edges on the boundary of the volume mesh");
    add(r.nonManifoldEdges, "non-manifold edges on the boundary of the volume mesh");
    add(r.misorientedEdges, "misoriented edges on the boundary of the volume mesh");
  } else {
    add(r.misorientedEdges, "edges where the orientations of the two faces disagree");
  }
}

}  // namespace

void QualityHistogram::add(double v) {
  min = count ? std::min(min, v) : v;
  max = count ? std::max(max, v) : v;
  sum += v;
  ++count;
  const int n = static_cast<int>(bins.size());
  const int b = static_cast<int>(std::floor((v - lo) / (hi - lo) * n));
  ++bins[std::clamp(b, 0, n - 1)];
}

MeshCheckReport checkMesh(const ReadMesh& m) {
  MeshCheckReport r;
  r.format = m.format;
  r.nodes = static_cast<long long>(m.nodes.size());
  r.elements = countTypes(m, nullptr);
  for (const MeshGroup& g : m.groups) r.groups.push_back({g.name, countTypes(m, &g.cells)});
  for (const NodeSet& s : m.nodeSets) r.nodeSets.emplace_back(s.name, static_cast<long long>(s.nodes.size()));

  std::vector<std::vector<int>> polygons;
  for (std::size_t i = 0; i < m.cellCount(); ++i) measure(m, i, r, polygons);
  r.volume = r.tetMeanRatio.count > 0;
  countEdges(r.volume ? tetBoundary(m, r) : polygons, r);
  listProblems(r);
  return r;
}

}  // namespace aniso::io
