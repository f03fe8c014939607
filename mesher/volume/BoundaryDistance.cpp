#include "mesher/volume/BoundaryDistance.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace aniso {
namespace {

/// Triangles per leaf of the tree.
constexpr std::uint32_t kLeafTriangles = 4;
/// Near-grid cells per near radius (cube at h 0.02: 1 cell per radius flagged points up to
/// two radii from the surface, 62 % of the distance searches found nothing within the
/// radius; with 2, a band of 1.5 radii).
constexpr double kNearCellsPerRadius = 2;

double boxDistance2(const Box3& b, const Vec3& x) {
  const Vec3 below = (b.lo - x).cwiseMax(0.0), above = (x - b.hi).cwiseMax(0.0);
  return below.squaredNorm() + above.squaredNorm();
}

}  // namespace

Vec3 closestPointOnTriangle(const Vec3& p, const Vec3& a, const Vec3& b, const Vec3& c) {
  const Vec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = ab.dot(ap), d2 = ac.dot(ap);
  if (d1 <= 0 && d2 <= 0) return a;
  const Vec3 bp = p - b;
  const double d3 = ab.dot(bp), d4 = ac.dot(bp);
  if (d3 >= 0 && d4 <= d3) return b;
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + d1 / (d1 - d3) * ab;
  const Vec3 cp = p - c;
  const double d5 = ab.dot(cp), d6 = ac.dot(cp);
  if (d6 >= 0 && d5 <= d6) return c;
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + d2 / (d2 - d6) * ac;
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (c - b);
  const double denom = va + vb + vc;
  if (!(denom > 0)) return a;  // degenerate triangle: a is on it
  return a + (vb / denom) * ab + (vc / denom) * ac;
}

TriangleTree::TriangleTree(std::span<const Vec3> points, std::span<const std::array<int, 3>> triangles,
                           double nearRadius) {
  // The points the triangles use, compacted (in order of first use), and the triangles as
  // index triples into them.
  std::vector<std::uint32_t> compact(points.size(), ~0u);
  tris_.reserve(triangles.size());
  std::vector<Vec3> centroids;
  centroids.reserve(triangles.size());
  for (const auto& t : triangles) {
    std::array<std::uint32_t, 3> c;
    for (int k = 0; k < 3; ++k) {
      std::uint32_t& id = compact[static_cast<std::size_t>(t[k])];
      if (id == ~0u) {
        id = static_cast<std::uint32_t>(points_.size());
        points_.push_back(points[t[k]]);
      }
      c[k] = id;
    }
    tris_.push_back(c);
    centroids.push_back((points[t[0]] + points[t[1]] + points[t[2]]) / 3.0);
  }
  points_.shrink_to_fit();
  if (!tris_.empty()) {
    // The tree is built over positions (perm: position -> triangle), the triangles moved
    // to their positions once at the end.
    std::vector<std::uint32_t> perm(tris_.size()), order;
    std::iota(perm.begin(), perm.end(), 0u);
    build(0, static_cast<std::uint32_t>(tris_.size()), centroids, perm, order);
    std::vector<std::array<std::uint32_t, 3>> sorted(tris_.size());
    for (std::size_t i = 0; i < perm.size(); ++i) sorted[i] = tris_[perm[i]];
    tris_ = std::move(sorted);
  }
  if (!tris_.empty() && nearRadius > 0 && std::isfinite(nearRadius)) buildNearGrid(nearRadius);
}

void TriangleTree::buildNearGrid(double radius) {
  Box3 domain = nodes_[0].box;
  domain.lo -= Vec3::Constant(radius);
  domain.hi += Vec3::Constant(radius);
  const Vec3 extent = domain.size();
  double cell = radius / kNearCellsPerRadius;
  const double volume = extent.prod();
  if (volume / (cell * cell * cell) > static_cast<double>(kMaxNearCells))
    cell = std::cbrt(volume / static_cast<double>(kMaxNearCells));
  for (int k = 0; k < 3; ++k)
    cells_[k] = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(extent[k] / cell)));
  while (cells_[0] * cells_[1] * cells_[2] > 2 * kMaxNearCells) {  // flat domains: ceil rounding
    cell *= 1.25;
    for (int k = 0; k < 3; ++k)
      cells_[k] = std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(extent[k] / cell)));
  }
  origin_ = domain.lo;
  cell_ = cell;
  nearRadius_ = radius;
  near_.assign((cells_[0] * cells_[1] * cells_[2] + 63) / 64, 0);
  auto index = [&](double x, int k) {
    const double i = std::floor((x - origin_[k]) / cell_);
    return static_cast<std::size_t>(std::clamp(i, 0.0, static_cast<double>(cells_[k] - 1)));
  };
  for (const auto& t : tris_) {
    Box3 b;
    for (const std::uint32_t p : t) b.add(points_[p]);
    std::array<std::size_t, 3> lo, hi;
    for (int k = 0; k < 3; ++k) lo[k] = index(b.lo[k] - radius, k), hi[k] = index(b.hi[k] + radius, k);
    for (std::size_t z = lo[2]; z <= hi[2]; ++z)
      for (std::size_t y = lo[1]; y <= hi[1]; ++y)
        for (std::size_t x = lo[0]; x <= hi[0]; ++x) {
          const std::size_t c = (z * cells_[1] + y) * cells_[0] + x;
          near_[c >> 6] |= std::uint64_t{1} << (c & 63);
        }
  }
}

bool TriangleTree::cellOf(const Vec3& x, std::size_t& cell) const {
  std::array<std::size_t, 3> i;
  for (int k = 0; k < 3; ++k) {
    const double c = std::floor((x[k] - origin_[k]) / cell_);
    if (!(c >= 0) || c >= static_cast<double>(cells_[k])) return false;  // outside the domain
    i[k] = static_cast<std::size_t>(c);
  }
  cell = (i[2] * cells_[1] + i[1]) * cells_[0] + i[0];
  return true;
}

bool TriangleTree::beyond(const Vec3& x, double distance) const {
  if (near_.empty() || !(distance <= nearRadius_)) return false;
  std::size_t cell;
  // Outside the domain (the triangles' box grown by the radius) or in a cell no grown
  // triangle box touches: farther than the radius from every triangle.
  return !cellOf(x, cell) || !((near_[cell >> 6] >> (cell & 63)) & 1u);
}

std::int32_t TriangleTree::build(std::uint32_t first, std::uint32_t count, const std::vector<Vec3>& centroids,
                                 std::vector<std::uint32_t>& perm, std::vector<std::uint32_t>& order) {
  const auto id = static_cast<std::int32_t>(nodes_.size());
  nodes_.emplace_back();
  Box3 box, cbox;
  for (std::uint32_t i = first; i < first + count; ++i) {
    for (const std::uint32_t p : tris_[perm[i]]) box.add(points_[p]);
    cbox.add(centroids[perm[i]]);
  }
  nodes_[id].box = box;
  if (count <= kLeafTriangles) {
    nodes_[id].first = first;
    nodes_[id].count = count;
    return id;
  }
  int axis = 0;
  cbox.size().maxCoeff(&axis);
  // Median split of the positions [first, first + count) by the centroid's coordinate
  // (position order breaks ties: deterministic).
  order.resize(count);
  std::iota(order.begin(), order.end(), first);
  const std::uint32_t half = count / 2;
  std::nth_element(order.begin(), order.begin() + half, order.end(), [&](std::uint32_t x, std::uint32_t y) {
    const double cx = centroids[perm[x]][axis], cy = centroids[perm[y]][axis];
    return cx < cy || (cx == cy && x < y);
  });
  for (std::uint32_t i = 0; i < count; ++i) order[i] = perm[order[i]];
  std::copy(order.begin(), order.end(), perm.begin() + first);
  const std::int32_t left = build(first, half, centroids, perm, order);
  const std::int32_t right = build(first + half, count - half, centroids, perm, order);
  nodes_[id].left = left;
  nodes_[id].right = right;
  return id;
}

bool TriangleTree::closest(const Vec3& x, double maxDistance, Vec3& out) const {
  if (nodes_.empty() || !(maxDistance >= 0)) return false;
  double best = maxDistance * maxDistance;
  bool found = false;
  std::int32_t stack[64];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const Node& n = nodes_[stack[--top]];
    if (boxDistance2(n.box, x) > best) continue;
    if (n.left < 0) {
      for (std::uint32_t i = n.first; i < n.first + n.count; ++i) {
        const auto& t = tris_[i];
        const Vec3 p = closestPointOnTriangle(x, points_[t[0]], points_[t[1]], points_[t[2]]);
        const double d2 = (p - x).squaredNorm();
        if (d2 <= best && (!found || d2 < best)) best = d2, out = p, found = true;
      }
      continue;
    }
    // The nearer child last on the stack: searched first.
    const double dl = boxDistance2(nodes_[n.left].box, x), dr = boxDistance2(nodes_[n.right].box, x);
    if (top + 2 > 64) continue;  // depth of a median-split tree: log2(triangles) < 64
    if (dl <= dr) {
      stack[top++] = n.right;
      stack[top++] = n.left;
    } else {
      stack[top++] = n.left;
      stack[top++] = n.right;
    }
  }
  return found;
}

}  // namespace aniso
