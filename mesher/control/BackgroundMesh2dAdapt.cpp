// BackgroundMesh2d: the adaptation procedures — point sources (sec. 3.4.1), continuous
// sources (3.4.2), parameterization (3.4.3) and the initialization with extrapolation.
#include <algorithm>
#include <cmath>

#include "mesher/control/BackgroundMesh2d.h"
#include "mesher/control/TensorDifference.h"
#include "mesher/core/Error.h"
#include "mesher/metric/MetricComparison.h"
#include "mesher/metric/MetricIntersection.h"
#include "mesher/metric/MetricInterpolation.h"
#include "mesher/predicates/Predicates.h"

namespace aniso {

using del2d::TriId;
using del2d::VertexId;

namespace {

/// Passes of an adaptation with A_o before it gives up on reaching a fixed point.
constexpr int kMaxAdaptPasses = 16;
/// Ring points are added only across edges longer than l_Mmax by this relative margin.
constexpr double kRingSlack = 1e-9;

/// Circumcentre of (a, b, c); not finite for a degenerate triangle.
Vec2 circumcentre(const Vec2& a, const Vec2& b, const Vec2& c) {
  const Vec2 ba = b - a, ca = c - a;
  const double d = 2 * (ba.x() * ca.y() - ba.y() * ca.x());
  const double b2 = ba.squaredNorm(), c2 = ca.squaredNorm();
  return a + Vec2(ca.y() * b2 - ba.y() * c2, ba.x() * c2 - ca.x() * b2) / d;
}

}  // namespace

double BackgroundMesh2d::maxEdgeMetricLength(TriId t, const Mat2& transformation) const {
  const Vec2& a = tri_.point(tri_.vertex(t, 0));
  const Vec2& b = tri_.point(tri_.vertex(t, 1));
  const Vec2& c = tri_.point(tri_.vertex(t, 2));
  return std::max({(transformation * (b - a)).norm(), (transformation * (c - b)).norm(),
                   (transformation * (a - c)).norm()});
}

bool BackgroundMesh2d::belowResolution(TriId t, const Metric2d& m, const Mat2& aux) const {
  double len = maxEdgeMetricLength(t, m.matrix() * aux);
  for (int i = 0; i < 3; ++i) {
    const std::uint32_t v = tri_.vertex(t, i).index;
    if (known_[v]) len = std::max(len, maxEdgeMetricLength(t, metric_[v].matrix() * aux_[v]));
  }
  return len < options_.minElementMetricLength;
}

bool BackgroundMesh2d::checkPoint(TriId t, Vec2& x) const {
  const Vec2& a = tri_.point(tri_.vertex(t, 0));
  const Vec2& b = tri_.point(tri_.vertex(t, 1));
  const Vec2& c = tri_.point(tri_.vertex(t, 2));
  x = (a + b + c) / 3;
  if (bounds_.contains(x)) return true;
  // A triangle reaching out of the bounds (towards the box corners) is checked at the
  // bounds point nearest to its centroid, when that point is in the triangle.
  x = clamp(x);
  return predicates::orient2d(a.data(), b.data(), x.data()) >= 0 &&
         predicates::orient2d(b.data(), c.data(), x.data()) >= 0 &&
         predicates::orient2d(c.data(), a.data(), x.data()) >= 0;
}

int BackgroundMesh2d::nearVertices(TriId t, std::uint32_t* out) const {
  int n = 0;
  const auto add = [&](TriId u) {
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t v = tri_.vertex(u, i).index;
      if (std::find(out, out + n, v) == out + n) out[n++] = v;
    }
  };
  add(t);
  for (int i = 0; i < 3; ++i)
    if (tri_.neighbour(t, i).valid()) add(tri_.neighbour(t, i));
  return n;
}

Vec2 BackgroundMesh2d::refinementPoint(TriId t, const Vec2& x) const {
  const Vec2& a = tri_.point(tri_.vertex(t, 0));
  const Vec2& b = tri_.point(tri_.vertex(t, 1));
  const Vec2& c = tri_.point(tri_.vertex(t, 2));
  const Vec2 cc = circumcentre(a, b, c);
  if (cc.allFinite()) {
    const Vec2 p = clamp(cc);
    if (predicates::incircle(a.data(), b.data(), c.data(), p.data()) > 0) return p;
  }
  return x;
}

void BackgroundMesh2d::refine(const NeedsRefinement& needs, const NewVertexValues& values) {
  std::vector<TriId> work;
  for (int pass = 0; pass < kMaxAdaptPasses; ++pass) {
    work.clear();
    for (std::uint32_t k = 0; k < tri_.triangleSlots(); ++k)
      if (tri_.isAlive(TriId(k))) work.push_back(TriId(k));
    std::size_t inserted = 0;
    while (!work.empty() && metric_.size() < options_.maxVertices) {
      const TriId t = work.back();
      work.pop_back();
      Vec2 x;
      if (!tri_.isAlive(t) || !checkPoint(t, x) || !needs(t, x)) continue;
      Vec2 p = refinementPoint(t, x);
      Metric2d m;
      Mat2 aux;
      bool known = values(p, t, m, aux);
      Inserted ins = insertVertex(p, m, aux, known, t);
      if (!ins.created && p != x) {  // the clamped circumcentre is an existing vertex
        p = x;
        known = values(p, t, m, aux);
        ins = insertVertex(p, m, aux, known, t);
      }
      if (!ins.created) continue;  // x is a vertex of t: nothing to refine there
      ++inserted;
      appendStar(ins.vertex, work);
    }
    // A_t and A_s sets of a triangle never change unless the triangle is replaced (and
    // then its replacements are checked): one pass is a fixed point. A_o sets reach
    // across the cavity, so a pass may spoil triangles checked earlier.
    if (inserted == 0 || options_.interpolation != BackgroundInterpolation::Neighbourhood) break;
  }
}

// ---- point sources (sec. 3.4.1) ----

void BackgroundMesh2d::insertDiscrete(const Vec2& x, const Metric2d& m) {
  if (!x.allFinite()) throw MeshingError("background mesh control space: point source at a non-finite point");
  const Modification done{*this};
  if (valued_)
    insertUpdate(clamp(x), m);
  else
    insertInitial(clamp(x), m);
}

void BackgroundMesh2d::insertInitial(const Vec2& p, const Metric2d& m) {
  std::uint32_t rng = 0x2545F491u;
  const TriId t = locateFrom(p, TriId(), rng);
  std::uint32_t set[kMaxNeighbourhood + 2];
  int n = gather(p, t, options_.interpolation, set);
  const Mat2 ap = auxExact_ ? auxExact_(p) : blendAux(p, set, n);
  // Proximity (step 1): merge into a vertex carrying a metric closer than ε_M in M_Q.
  const Mat2 tq = m.matrix() * ap;
  n = nearVertices(t, set);
  int best = -1;
  double bestD = epsM_;
  for (int i = 0; i < n; ++i) {
    if (!known_[set[i]]) continue;
    const double d = (tq * (point(static_cast<int>(set[i])) - p)).norm();
    if (d < bestD) {
      bestD = d;
      best = static_cast<int>(set[i]);
    }
  }
  if (best >= 0) {
    intersectVertex(best, m);
    return;
  }
  const Inserted ins = insertVertex(p, m, ap, true, t);
  if (ins.created) {
    ++pending_;
  } else if (ins.vertex >= 0) {  // exactly on a vertex (ε_M = 0)
    if (known_[ins.vertex]) {
      intersectVertex(ins.vertex, m);
    } else {
      setVertex(ins.vertex, m);
      known_[ins.vertex] = 1;
      ++pending_;
    }
  }
}

void BackgroundMesh2d::insertUpdate(const Vec2& p, const Metric2d& m) {
  std::uint32_t rng = 0x2545F491u;
  const TriId t = locateFrom(p, TriId(), rng);
  std::uint32_t set[kMaxNeighbourhood + 2];
  int n = gather(p, t, options_.interpolation, set);
  const Metric2d current = blendMetric(p, set, n);
  const Mat2 ap = blendAux(p, set, n);
  if (metricDifference(m, current) < epsDelta_) return;  // step 2
  const Metric2d updated = intersect(m, current);        // step 3
  if (metricDifference(updated, current) < epsDelta_) return;  // step 4
  const Mat2 tq = m.matrix() * ap;
  // Proximity of control vertices (3.4.1 step 1).
  n = nearVertices(t, set);
  int best = -1;
  double bestD = epsM_;
  for (int i = 0; i < n; ++i) {
    const double d = (tq * (point(static_cast<int>(set[i])) - p)).norm();
    if (d < bestD) {
      bestD = d;
      best = static_cast<int>(set[i]);
    }
  }
  if (best >= 0) {
    intersectVertex(best, m);
    return;
  }
  // Step 5, size sensitivity: a containing triangle already short in M_Q only has its
  // vertices intersected (as the quadtree's leaf corners); a long one is "split" by
  // inserting Q itself, with a ring that keeps the change local.
  const auto intersectTriangle = [&] {
    for (int i = 0; i < 3; ++i) intersectVertex(static_cast<int>(tri_.vertex(t, i).index), m);
  };
  if (maxEdgeMetricLength(t, tq) <= lMax_ || metric_.size() >= options_.maxVertices) {
    intersectTriangle();
    return;
  }
  const Inserted ins = insertVertex(p, updated, auxExact_ ? auxExact_(p) : ap, true, t);
  if (!ins.created) {
    if (ins.vertex >= 0) intersectVertex(ins.vertex, m);
    return;
  }
  addRing(ins.vertex, p, current, tq);
}

void BackgroundMesh2d::addRing(int q, const Vec2& x, const Metric2d& before, const Mat2& tq) {
  // Every edge from Q longer than l_Mmax in M_Q gets a vertex at metric distance l_Mmax
  // from Q carrying the field as it was before Q (eq. 2.18 between the old value at Q and
  // the far vertex): the mesh counterpart of the quadtree's splits down to leaves of
  // l_Mmax around the source, so the source changes the field only within that distance.
  std::vector<int> around;
  for (int round = 0; round < options_.maxRingRounds; ++round) {
    neighbours(q, around);
    int added = 0;
    for (int w : around) {
      if (metric_.size() >= options_.maxVertices) return;
      const Vec2 d = point(w) - x;
      const double len = (tq * d).norm();
      if (len <= lMax_ * (1 + kRingSlack)) continue;
      const double s = lMax_ / len;
      const Vec2 r = clamp(x + s * d);
      const Metric2d mr = interpolate(before, metric_[w], s);
      const Mat2 ar = auxExact_ ? auxExact_(r) : Mat2((1 - s) * aux_[q] + s * aux_[w]);
      if (insertVertex(r, mr, ar, true, tri_.vertexTriangle(VertexId(static_cast<std::uint32_t>(q)))).created) ++added;
    }
    if (added == 0) return;
  }
}

void BackgroundMesh2d::initializeVertices() {
  if (pending_ == 0) {
    if (valued_) return;
    throw MeshingError("background mesh control space: no metric source to initialize the control vertices from");
  }
  const Modification done{*this};
  const VertexGraph g = graph();
  std::vector<double> len(g.edges.size());
  for (std::size_t e = 0; e < g.edges.size(); ++e) len[e] = (point(g.edges[e][1]) - point(g.edges[e][0])).norm();
  extrapolateLayers<2>(g, len, known_, metric_);
  for (std::size_t v = 0; v < metric_.size(); ++v) length_[v] = metric_[v].inverseMatrix();
  valued_ = true;
  pending_ = 0;
}

// ---- continuous sources (sec. 3.4.2) ----

void BackgroundMesh2d::addInitialGrid() {
  const Vec2 size = bounds_.size();
  const double step = size.maxCoeff() / (options_.initialGrid - 1);
  int n[2];
  for (int k = 0; k < 2; ++k) n[k] = size(k) > 0 ? std::max(2, static_cast<int>(std::lround(size(k) / step)) + 1) : 1;
  TriId near;
  for (int j = 0; j < n[1]; ++j)
    for (int i = 0; i < n[0]; ++i) {
      const double u = n[0] > 1 ? double(i) / (n[0] - 1) : 0.5, v = n[1] > 1 ? double(j) / (n[1] - 1) : 0.5;
      const Vec2 p = clamp(bounds_.lo + Vec2(u * size.x(), v * size.y()));
      const Mat2 aux = auxExact_ ? auxExact_(p) : Mat2::Identity();
      const Inserted ins = insertVertex(p, Metric2d(), aux, false, near);
      if (ins.created) near = tri_.vertexTriangle(VertexId(static_cast<std::uint32_t>(ins.vertex)));
    }
}

void BackgroundMesh2d::setContinuous(const MetricFn& source) {
  const Modification done{*this};
  const bool had = valued_;
  const bool exact = !had && pending_ == 0;  // the field must reproduce the source
  if (!had) addInitialGrid();
  for (int v = 0; v < vertexCount(); ++v) {
    const Metric2d s = source(clamp(point(v)));
    setVertex(v, known_[v] ? intersect(metric_[v], s) : s);
    known_[v] = 1;
  }
  valued_ = true;
  pending_ = 0;
  const auto fails = [&](TriId t, const Vec2& x) {
    const Metric2d target = source(x);
    std::uint32_t set[kMaxNeighbourhood + 2];
    const int n = gather(x, t, options_.interpolation, set);
    const Metric2d field = blendMetric(x, set, n);
    // Fresh: the field must reproduce the source. Valued: only where the source asks for
    // a finer metric than the field (where earlier sources are finer, refining could
    // never bring the two closer).
    const Metric2d goal = exact ? target : intersect(field, target);
    if (metricDifference(goal, field) <= epsDelta_) return false;
    return !belowResolution(t, target, blendAux(x, set, n));
  };
  const auto needs = [&](TriId t, const Vec2& x) {
    if (fails(t, x)) return true;
    if (options_.check == BackgroundCheck::Centroid) return false;
    for (int i = 0; i < 3; ++i) {
      const Vec2 mid = 0.5 * (tri_.point(tri_.vertex(t, (i + 1) % 3)) + tri_.point(tri_.vertex(t, (i + 2) % 3)));
      if (bounds_.contains(mid) && fails(t, mid)) return true;
    }
    return false;
  };
  const auto values = [&](const Vec2& p, TriId near, Metric2d& m, Mat2& aux) {
    Metric2d field;
    fieldNear(p, near, &field, &aux);
    const Metric2d s = source(p);
    m = exact ? s : intersect(field, s);
    if (auxExact_) aux = auxExact_(p);
    return true;
  };
  refine(needs, values);
}

// ---- parameterization (sec. 3.4.3) ----

void BackgroundMesh2d::adaptAux(const MatFn& exact) {
  const Modification done{*this};
  for (int v = 0; v < vertexCount(); ++v) aux_[v] = exact(clamp(point(v)));
  hasAux_ = true;
  auxExact_ = exact;
  const auto needs = [&](TriId t, const Vec2& c) {  // the check point of 3.3.3 only
    const Mat2 centre = exact(c);
    std::uint32_t set[kMaxNeighbourhood + 2];
    const int n = gather(c, t, options_.interpolation, set);
    double worst = tensorDifference<2>(centre, blendAux(c, set, n));
    for (int i = 0; i < 3; ++i) worst = std::max(worst, tensorDifference<2>(centre, aux_[tri_.vertex(t, i).index]));
    if (worst <= epsDelta_) return false;
    return !(valued_ && belowResolution(t, blendMetric(c, set, n), centre));
  };
  const auto values = [&](const Vec2& p, TriId near, Metric2d& m, Mat2& aux) {
    aux = exact(p);
    if (!valued_) return false;  // extrapolated by initializeVertices
    fieldNear(p, near, &m, nullptr);
    return true;
  };
  refine(needs, values);
}

}  // namespace aniso
