// BackgroundMesh3d: the adaptation procedures — point sources (sec. 3.4.1), continuous
// sources (3.4.2) and the initialization with extrapolation (see BackgroundMesh2dAdapt.cpp
// for the 2D counterparts and the reasoning).
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

#include "mesher/control/BackgroundMesh3d.h"
#include "mesher/core/Error.h"
#include "mesher/metric/MetricComparison.h"
#include "mesher/metric/MetricIntersection.h"
#include "mesher/metric/MetricInterpolation.h"
#include "mesher/predicates/Predicates.h"

namespace aniso {

using del3d::TetId;
using del3d::VertexId;

namespace {

constexpr int kMaxAdaptPasses = 16;
constexpr double kRingSlack = 1e-9;
constexpr int kEdge[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

/// Largest shift of an interior initial-grid coordinate, in grid steps.
constexpr double kGridJitter = 0.1;

/// A deterministic pseudo-random number in [0, 1) from grid indices (splitmix64).
double unitHash(int i, int j, int l, int k) {
  std::uint64_t z = (std::uint64_t(i) * 0x9E3779B97F4A7C15ull) ^ (std::uint64_t(j) << 21) ^ (std::uint64_t(l) << 42) ^
                    std::uint64_t(k) * 0xD1B54A32D192ED03ull;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return double(z >> 11) * 0x1.0p-53;
}

/// Circumcentre of the tetrahedron (a, b, c, d); not finite when it is flat.
Vec3 circumcentre(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  const Vec3 ba = b - a, ca = c - a, da = d - a;
  const Vec3 n = ba.squaredNorm() * ca.cross(da) + ca.squaredNorm() * da.cross(ba) + da.squaredNorm() * ba.cross(ca);
  return a + n / (2 * ba.dot(ca.cross(da)));
}

}  // namespace

double BackgroundMesh3d::maxEdgeMetricLength(TetId t, const Mat3& m) const {
  const std::uint32_t* tv = mesh_->tetVertices(t);
  double len = 0;
  for (const auto& e : kEdge)
    len = std::max(len, (m * (mesh_->point(VertexId(tv[e[1]])) - mesh_->point(VertexId(tv[e[0]])))).norm());
  return len;
}

bool BackgroundMesh3d::belowResolution(TetId t, const Metric3d& m) const {
  double len = maxEdgeMetricLength(t, m.matrix());
  const std::uint32_t* tv = mesh_->tetVertices(t);
  for (int i = 0; i < 4; ++i)
    if (known_[tv[i]]) len = std::max(len, maxEdgeMetricLength(t, metric_[tv[i]].matrix()));
  return len < options_.minElementMetricLength;
}

bool BackgroundMesh3d::checkPoint(TetId t, Vec3& x) const {
  x = centroid(t);
  if (bounds_.contains(x)) return true;
  // A tetrahedron reaching out of the bounds (towards the box corners) is checked at the
  // bounds point nearest to its centroid, when that point is in the tetrahedron.
  x = clamp(x);
  const std::uint32_t* tv = mesh_->tetVertices(t);
  for (int i = 0; i < 4; ++i) {
    const double* c[4] = {mesh_->coords(VertexId(tv[0])), mesh_->coords(VertexId(tv[1])),
                          mesh_->coords(VertexId(tv[2])), mesh_->coords(VertexId(tv[3]))};
    c[i] = x.data();
    if (predicates::orient3d(c[0], c[1], c[2], c[3]) < 0) return false;
  }
  return true;
}

int BackgroundMesh3d::nearVertices(TetId t, std::uint32_t* out) const {
  int n = 0;
  const auto add = [&](TetId u) {
    for (int i = 0; i < 4; ++i) {
      const std::uint32_t v = mesh_->vertex(u, i).index;
      if (std::find(out, out + n, v) == out + n) out[n++] = v;
    }
  };
  add(t);
  for (int i = 0; i < 4; ++i)
    if (mesh_->neighbour(t, i).valid()) add(mesh_->neighbour(t, i));
  return n;
}

Vec3 BackgroundMesh3d::refinementPoint(TetId t, const Vec3& x) const {
  const std::uint32_t* tv = mesh_->tetVertices(t);
  const Vec3 a = mesh_->point(VertexId(tv[0])), b = mesh_->point(VertexId(tv[1])),
             c = mesh_->point(VertexId(tv[2])), d = mesh_->point(VertexId(tv[3]));
  const Vec3 cc = circumcentre(a, b, c, d);
  if (cc.allFinite()) {
    const Vec3 p = clamp(cc);
    if (predicates::insphere(a.data(), b.data(), c.data(), d.data(), p.data()) > 0) return p;
  }
  return x;
}

void BackgroundMesh3d::refine(const NeedsRefinement& needs, const NewVertexValues& values) {
  std::vector<TetId> work;
  for (int pass = 0; pass < kMaxAdaptPasses; ++pass) {
    work.clear();
    for (std::uint32_t k = 0; k < mesh_->tetSlots(); ++k)
      if (mesh_->isAlive(TetId(k))) work.push_back(TetId(k));
    std::size_t inserted = 0;
    while (!work.empty() && metric_.size() < options_.maxVertices) {
      const TetId t = work.back();
      work.pop_back();
      Vec3 x;
      if (!mesh_->isAlive(t) || !checkPoint(t, x) || !needs(t, x)) continue;
      Vec3 p = refinementPoint(t, x);
      Metric3d m;
      values(p, t, m);
      Inserted ins = insertVertex(p, m, true, t);
      if (!ins.created && p != x) {  // the clamped circumcentre is an existing vertex
        p = x;
        values(p, t, m);
        ins = insertVertex(p, m, true, t);
      }
      if (!ins.created) continue;
      ++inserted;
      const auto fresh = inserter_->newTets();
      work.insert(work.end(), fresh.begin(), fresh.end());
    }
    if (inserted == 0 || options_.interpolation != BackgroundInterpolation::Neighbourhood) break;
  }
}

// ---- point sources (sec. 3.4.1) ----

void BackgroundMesh3d::insertDiscrete(const Vec3& x, const Metric3d& m) {
  if (!x.allFinite()) throw MeshingError("background mesh control space: point source at a non-finite point");
  const Modification done{*this};
  if (valued_)
    insertUpdate(clamp(x), m);
  else
    insertInitial(clamp(x), m);
}

void BackgroundMesh3d::insertInitial(const Vec3& p, const Metric3d& m) {
  std::uint32_t rng = 0x2545F491u;
  const TetId t = locateFrom(p, TetId(), rng);
  std::uint32_t set[8];
  const int n = nearVertices(t, set);
  int best = -1;
  double bestD = epsM_;
  for (int i = 0; i < n; ++i) {
    if (!known_[set[i]]) continue;
    const double d = m.distance(p, point(static_cast<int>(set[i])));
    if (d < bestD) {
      bestD = d;
      best = static_cast<int>(set[i]);
    }
  }
  if (best >= 0) {
    intersectVertex(best, m);
    return;
  }
  const Inserted ins = insertVertex(p, m, true, t);
  if (ins.created) {
    ++pending_;
  } else if (ins.vertex >= 0) {
    if (known_[ins.vertex]) {
      intersectVertex(ins.vertex, m);
    } else {
      setVertex(ins.vertex, m);
      known_[ins.vertex] = 1;
      ++pending_;
    }
  }
}

void BackgroundMesh3d::insertUpdate(const Vec3& p, const Metric3d& m) {
  std::uint32_t rng = 0x2545F491u;
  const TetId t = locateFrom(p, TetId(), rng);
  std::uint32_t set[kMaxNeighbourhood + 3];
  int n = gather(p, t, options_.interpolation, set);
  const Metric3d current = blendMetric(p, set, n);
  if (metricDifference(m, current) < epsDelta_) return;        // step 2
  const Metric3d updated = intersect(m, current);              // step 3
  if (metricDifference(updated, current) < epsDelta_) return;  // step 4
  n = nearVertices(t, set);
  int best = -1;
  double bestD = epsM_;
  for (int i = 0; i < n; ++i) {
    const double d = m.distance(p, point(static_cast<int>(set[i])));
    if (d < bestD) {
      bestD = d;
      best = static_cast<int>(set[i]);
    }
  }
  if (best >= 0) {
    intersectVertex(best, m);
    return;
  }
  if (maxEdgeMetricLength(t, m.matrix()) <= lMax_ || metric_.size() >= options_.maxVertices) {
    for (int i = 0; i < 4; ++i) intersectVertex(static_cast<int>(mesh_->vertex(t, i).index), m);
    return;
  }
  const Inserted ins = insertVertex(p, updated, true, t);
  if (!ins.created) {
    if (ins.vertex >= 0) intersectVertex(ins.vertex, m);
    return;
  }
  addRing(ins.vertex, p, current, m.matrix());
}

void BackgroundMesh3d::addRing(int q, const Vec3& x, const Metric3d& before, const Mat3& m) {
  std::vector<int> around;
  for (int round = 0; round < options_.maxRingRounds; ++round) {
    neighbours(q, around);
    int added = 0;
    for (int w : around) {
      if (metric_.size() >= options_.maxVertices) return;
      const Vec3 d = point(w) - x;
      const double len = (m * d).norm();
      if (len <= lMax_ * (1 + kRingSlack)) continue;
      const double s = lMax_ / len;
      const Vec3 r = clamp(x + s * d);
      if (insertVertex(r, interpolate(before, metric_[w], s), true, mesh_->vertexTet(VertexId(static_cast<std::uint32_t>(q))))
              .created)
        ++added;
    }
    if (added == 0) return;
  }
}

void BackgroundMesh3d::initializeVertices() {
  if (pending_ == 0) {
    if (valued_) return;
    throw MeshingError("background mesh control space: no metric source to initialize the control vertices from");
  }
  const Modification done{*this};
  const VertexGraph g = graph();
  std::vector<double> len(g.edges.size());
  for (std::size_t e = 0; e < g.edges.size(); ++e) len[e] = (point(g.edges[e][1]) - point(g.edges[e][0])).norm();
  extrapolateLayers<3>(g, len, known_, metric_);
  for (std::size_t v = 0; v < metric_.size(); ++v) length_[v] = metric_[v].inverseMatrix();
  valued_ = true;
  pending_ = 0;
}

// ---- continuous sources (sec. 3.4.2) ----

void BackgroundMesh3d::addInitialGrid() {
  const Vec3 size = bounds_.size();
  const double step = size.maxCoeff() / (options_.initialGrid - 1);
  int n[3];
  for (int k = 0; k < 3; ++k) n[k] = size(k) > 0 ? std::max(2, static_cast<int>(std::lround(size(k) / step)) + 1) : 1;
  TetId near;
  for (int l = 0; l < n[2]; ++l)
    for (int j = 0; j < n[1]; ++j)
      for (int i = 0; i < n[0]; ++i) {
        Vec3 f;
        const int idx[3] = {i, j, l};
        for (int k = 0; k < 3; ++k) {
          f(k) = n[k] > 1 ? double(idx[k]) / (n[k] - 1) : 0.5;
          // Interior coordinates are shifted by up to ±kGridJitter of a step: the eight
          // cospherical corners of every cell of an exact grid would send every in-sphere
          // test of the insertion to exact arithmetic (measured: 60 % of the build time).
          if (idx[k] > 0 && idx[k] < n[k] - 1)
            f(k) += kGridJitter * (2 * unitHash(i, j, l, k) - 1) / (n[k] - 1);
        }
        const Inserted ins = insertVertex(clamp(bounds_.lo + f.cwiseProduct(size)), Metric3d(), false, near);
        if (ins.created) near = mesh_->vertexTet(VertexId(static_cast<std::uint32_t>(ins.vertex)));
      }
}

void BackgroundMesh3d::setContinuous(const MetricFn& source) {
  const Modification done{*this};
  const bool had = valued_;
  const bool exact = !had && pending_ == 0;
  if (!had) addInitialGrid();
  for (int v = 0; v < vertexCount(); ++v) {
    const Metric3d s = source(clamp(point(v)));
    setVertex(v, known_[v] ? intersect(metric_[v], s) : s);
    known_[v] = 1;
  }
  valued_ = true;
  pending_ = 0;
  const auto fails = [&](TetId t, const Vec3& x) {
    const Metric3d target = source(x);
    std::uint32_t set[kMaxNeighbourhood + 3];
    const Metric3d field = blendMetric(x, set, gather(x, t, options_.interpolation, set));
    const Metric3d goal = exact ? target : intersect(field, target);
    if (metricDifference(goal, field) <= epsDelta_) return false;
    return !belowResolution(t, target);
  };
  const auto needs = [&](TetId t, const Vec3& x) {
    if (fails(t, x)) return true;
    if (options_.check == BackgroundCheck::Centroid) return false;
    const std::uint32_t* tv = mesh_->tetVertices(t);
    for (const auto& e : kEdge) {
      const Vec3 mid = 0.5 * (mesh_->point(VertexId(tv[e[0]])) + mesh_->point(VertexId(tv[e[1]])));
      if (bounds_.contains(mid) && fails(t, mid)) return true;
    }
    return false;
  };
  const auto values = [&](const Vec3& p, TetId near, Metric3d& m) {
    const Metric3d s = source(p);
    m = exact ? s : intersect(fieldNear(p, near), s);
  };
  refine(needs, values);
}

}  // namespace aniso
