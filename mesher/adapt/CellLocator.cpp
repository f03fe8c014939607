#include "mesher/adapt/CellLocator.h"

#include <algorithm>
#include <cmath>

#include <Eigen/Dense>

#include "mesher/volume/BoundaryDistance.h"

namespace aniso {
namespace {

/// Bins per axis at most (the grid of a very flat or long mesh stays small).
constexpr int kMaxBinsPerAxis = 1024;

/// Barycentric coordinates of q in the triangle (a, b, c) (q on its plane or projected).
std::array<double, 4> triangleBary(const Vec3& q, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 e1 = b - a, e2 = c - a, d = q - a;
  const double g11 = e1.dot(e1), g12 = e1.dot(e2), g22 = e2.dot(e2);
  const double det = g11 * g22 - g12 * g12;
  if (!(det > 0)) return {1, 0, 0, 0};
  const double s = (g22 * e1.dot(d) - g12 * e2.dot(d)) / det, t = (g11 * e2.dot(d) - g12 * e1.dot(d)) / det;
  return {1 - s - t, s, t, 0};
}

/// Negative coordinates (rounding of a closest point on the boundary) set to 0, sum 1.
void clampBary(std::array<double, 4>& l, int k) {
  double sum = 0;
  for (int i = 0; i < k; ++i) sum += (l[i] = std::max(l[i], 0.0));
  for (int i = 0; i < k; ++i) l[i] /= sum;
}

}  // namespace

CellLocator::CellLocator(const PatchMesh& mesh) : mesh_(mesh) {
  const std::size_t n = mesh.cellCount();
  if (n == 0) return;
  Box3 all;
  std::vector<Box3> boxes(n);
  double measure = 0;
  for (std::size_t c = 0; c < n; ++c) {
    for (int k = 0; k < mesh.corners(); ++k) boxes[c].add(mesh.nodes[mesh.conn[mesh.offsets[c] + k]]);
    all.add(boxes[c]);
    measure += cellMeasure(mesh, c);
  }
  // bins of the cells' mean size, kCellsPerBin of them in each
  const double mean = std::pow(measure / static_cast<double>(n), 1.0 / mesh.dim);
  bin_ = std::max({mean * std::pow(kCellsPerBin, 1.0 / mesh.dim), all.diagonal() / kMaxBinsPerAxis,
                   all.diagonal() * 1e-12});
  origin_ = all.lo;
  for (int a = 0; a < 3; ++a)
    bins_[a] = std::clamp(static_cast<int>(std::ceil(all.size()[a] / bin_)), 1, kMaxBinsPerAxis);
  const std::size_t total = static_cast<std::size_t>(bins_[0]) * bins_[1] * bins_[2];
  std::vector<std::array<int, 3>> lo(n), hi(n);
  std::vector<int> count(total + 1, 0);
  auto each = [&](std::size_t c, auto&& f) {
    for (int z = lo[c][2]; z <= hi[c][2]; ++z)
      for (int y = lo[c][1]; y <= hi[c][1]; ++y)
        for (int x = lo[c][0]; x <= hi[c][0]; ++x) f((static_cast<std::size_t>(z) * bins_[1] + y) * bins_[0] + x);
  };
  for (std::size_t c = 0; c < n; ++c) {
    lo[c] = binOf(boxes[c].lo), hi[c] = binOf(boxes[c].hi);
    each(c, [&](std::size_t b) { ++count[b + 1]; });
  }
  for (std::size_t b = 0; b < total; ++b) count[b + 1] += count[b];
  first_ = count;
  cells_.resize(static_cast<std::size_t>(first_[total]));
  for (std::size_t c = 0; c < n; ++c) each(c, [&](std::size_t b) { cells_[count[b]++] = static_cast<int>(c); });
}

std::array<int, 3> CellLocator::binOf(const Vec3& x) const {
  std::array<int, 3> b;
  for (int a = 0; a < 3; ++a) b[a] = std::clamp(static_cast<int>(std::floor((x[a] - origin_[a]) / bin_)), 0, bins_[a] - 1);
  return b;
}

CellHit CellLocator::distanceTo(int c, const Vec3& x) const {
  const int* v = mesh_.conn.data() + mesh_.offsets[c];
  const Vec3& a = mesh_.nodes[v[0]];
  const Vec3& b = mesh_.nodes[v[1]];
  const Vec3& d = mesh_.nodes[v[2]];
  CellHit hit;
  hit.cell = c;
  if (mesh_.dim == 2) {
    const Vec3 q = closestPointOnTriangle(x, a, b, d);
    hit.distance = (x - q).norm();
    hit.bary = triangleBary(q, a, b, d);
    clampBary(hit.bary, 3);
    return hit;
  }
  const Vec3& e = mesh_.nodes[v[3]];
  Mat3 m;
  m << b - a, d - a, e - a;
  const Vec3 s = m.fullPivLu().solve(x - a);
  hit.bary = {1 - s.sum(), s[0], s[1], s[2]};
  if (std::all_of(hit.bary.begin(), hit.bary.end(), [](double l) { return l >= -kInsideTolerance; })) {
    clampBary(hit.bary, 4);
    return hit;
  }
  // outside: the closest point of its four faces
  const std::array<int, 4> corner{v[0], v[1], v[2], v[3]};
  hit.distance = std::numeric_limits<double>::infinity();
  for (int skip = 0; skip < 4; ++skip) {
    std::array<int, 3> f;
    for (int i = 0, k = 0; i < 4; ++i)
      if (i != skip) f[k++] = i;
    const Vec3& p0 = mesh_.nodes[corner[f[0]]];
    const Vec3& p1 = mesh_.nodes[corner[f[1]]];
    const Vec3& p2 = mesh_.nodes[corner[f[2]]];
    const Vec3 q = closestPointOnTriangle(x, p0, p1, p2);
    const double dist = (x - q).norm();
    if (dist >= hit.distance) continue;
    hit.distance = dist;
    const std::array<double, 4> t = triangleBary(q, p0, p1, p2);
    hit.bary = {0, 0, 0, 0};
    for (int k = 0; k < 3; ++k) hit.bary[f[k]] = t[k];
  }
  clampBary(hit.bary, 4);
  return hit;
}

CellHit CellLocator::locate(const Vec3& x) const {
  CellHit best;
  if (mesh_.cellCount() == 0) return best;
  best.distance = std::numeric_limits<double>::infinity();
  const std::array<int, 3> at = binOf(x);
  const int maxRing = std::max({bins_[0], bins_[1], bins_[2]});
  for (int r = 0; r <= maxRing; ++r) {
    for (int z = at[2] - r; z <= at[2] + r; ++z)
      for (int y = at[1] - r; y <= at[1] + r; ++y)
        for (int xb = at[0] - r; xb <= at[0] + r; ++xb) {
          const bool shell = std::max({std::abs(z - at[2]), std::abs(y - at[1]), std::abs(xb - at[0])}) == r;
          if (!shell || z < 0 || y < 0 || xb < 0 || z >= bins_[2] || y >= bins_[1] || xb >= bins_[0]) continue;
          const std::size_t b = (static_cast<std::size_t>(z) * bins_[1] + y) * bins_[0] + xb;
          for (int k = first_[b]; k < first_[b + 1]; ++k) {
            const CellHit h = distanceTo(cells_[k], x);
            if (h.distance < best.distance || (h.distance == best.distance && h.cell < best.cell)) best = h;
          }
        }
    // a cell only in bins beyond ring r is at least r bins from x (x projected on the grid)
    if (best.distance <= r * bin_) break;
  }
  return best;
}

}  // namespace aniso
