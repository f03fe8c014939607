#include "mesher/surface/face/Refinement.h"

#include "mesher/core/Segment.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "mesher/delaunay/Attributes2d.h"
#include "mesher/delaunay/InsertPoint.h"
#include "mesher/delaunay/Workspace2d.h"
#include "mesher/surface/face/FaceMetric.h"
#include "mesher/surface/face/FrontalPoint.h"
#include "mesher/surface/face/InnerAngleSwaps.h"
#include "mesher/surface/face/VisibleWalk.h"

namespace aniso::face {

using namespace del2d;

namespace {

/// The fold guard as the insertion's new-triangle test: (p, a, b) upright on the surface.
class UprightFan final : public NewTriangleTest {
 public:
  UprightFan(const SurfaceLift* lift, const Vec2& p) : lift_(lift) {
    if (lift_) p_ = lift_->lift(p);
  }
  bool accept(const Triangulation2d& tri, VertexId a, VertexId b) const override {
    return SurfaceLift::upright(p_, lift_->at(tri, a), lift_->at(tri, b));
  }
  const LiftedPoint& point() const { return p_; }

 private:
  const SurfaceLift* lift_;
  LiftedPoint p_;
};

struct HeapEntry {
  double q;
  std::uint32_t tri;
  std::uint32_t stamp;
};

/// std heap functions build a max-heap: "lower priority" = larger q, then larger slot.
struct LowerPriority {
  bool operator()(const HeapEntry& x, const HeapEntry& y) const {
    return x.q > y.q || (x.q == y.q && (x.tri > y.tri || (x.tri == y.tri && x.stamp > y.stamp)));
  }
};

/// Metric distance from p to the segment [x, y] under m.
double segmentDistance(const Mat2& m, const Vec2& p, const Vec2& x, const Vec2& y) {
  return distanceToSegment<Vec2>(m * p, m * x, m * y);
}

class Refiner {
 public:
  Refiner(Triangulation2d& tri, const ControlSpace2d& cs, const RefineOptions& opt)
      : tri_(tri), cs_(cs), opt_(opt), vertexMetric_(tri, Mat2::Identity()), triMetric_(tri, Mat2::Identity()),
        stamp_(tri, 0u), quality_(tri, 0.0), queued_(tri, kNotQueued), area_(tri, 0.0), counted_(tri, 0),
        frontal_(opt.frontal) {}

  RefineStats run() {
    initialise();
    if (opt_.onPrediction) opt_.onPrediction(stats_.predictedTriangles);
    std::size_t pops = 0;
    CancelPoll cancel(opt_.cancel, "surface refinement", 256);
    for (;;) {
      cancel.tick();
      if (heap_.empty()) {
        // Frontal phase over: whatever is still bad (regions the front never reached,
        // triangles whose frontal point was cancelled) gets the mixed MLE/CCS method.
        if (!frontal_) break;
        frontal_ = false;
        for (std::uint32_t s = 0; s < tri_.triangleSlots(); ++s) {
          const TriId t(s);
          if (tri_.isAlive(t) && quality_[t] < opt_.qualityThreshold && !isQueued(t)) push(t, quality_[t]);
        }
        if (heap_.empty()) break;
      }
      std::pop_heap(heap_.begin(), heap_.end(), LowerPriority());
      const HeapEntry e = heap_.back();
      heap_.pop_back();
      if (opt_.onPrediction && ++pops % opt_.predictionInterval == 0) opt_.onPrediction(predictFinal(e.q));
      const TriId t(e.tri);
      if (!tri_.isAlive(t) || stamp_[t] != e.stamp) continue;
      if (stats_.inserted >= stats_.insertionLimit) {
        stats_.limitReached = true;
        break;
      }
      if (!refine(t, e.q)) ++stats_.cancelled;
    }
    return stats_;
  }

 private:
  /// Vertex metrics, evaluation of every live triangle, the prediction of eq. 6.2.
  void initialise() {
    for (std::uint32_t v = 0; v < tri_.numVertices(); ++v) {
      const VertexId id(v);
      if (tri_.vertexTriangle(id).valid()) vertexMetric_[id] = metricAt(cs_, tri_.point(id));
    }
    double metricArea = 0;
    heap_.reserve(2 * tri_.numTriangles());
    for (std::uint32_t k = 0; k < tri_.triangleSlots(); ++k)
      if (tri_.isAlive(TriId(k))) {
        evaluate(TriId(k));
        count(TriId(k));
      }
    for (std::uint32_t k = 0; k < tri_.triangleSlots(); ++k) {
      const TriId t(k);
      if (!tri_.isAlive(t)) continue;
      const double q = quality_[t];
      if (q < opt_.qualityThreshold && (!frontal_ || frontEdge(t) >= 0)) push(t, q);
      const std::uint32_t* tv = tri_.triVertices(t);
      const Vec2 &a = tri_.point(VertexId(tv[0])), &b = tri_.point(VertexId(tv[1])), &c = tri_.point(VertexId(tv[2]));
      double det = 0;  // the largest finite |det M| of the four samples (unusable metrics skipped)
      const auto sample = [&det](const Mat2& m) {
        const double d = std::abs(m.determinant());
        if (std::isfinite(d)) det = std::max(det, d);
      };
      sample(triMetric_[t]);
      for (int i = 0; i < 3; ++i) sample(vertexMetric_[VertexId(tv[i])]);
      const double area = 0.5 * std::abs(cross2(b - a, c - a)) * det;
      if (std::isfinite(area)) metricArea += area;
    }
    stats_.predictedTriangles = std::isfinite(metricArea) ? metricArea / kIdealTriangleArea : 1e12;
    const double limit = opt_.insertionLimitFactor * std::min(stats_.predictedTriangles, 1e12) +
                         static_cast<double>(opt_.insertionLimitExtra);
    stats_.insertionLimit = static_cast<std::size_t>(std::min(limit, 4e9));
    const auto expected = static_cast<std::size_t>(std::min(stats_.predictedTriangles, 2e8));
    tri_.reserve(tri_.numVertices() + expected / 2 + 16, tri_.triangleSlots() + expected + 16);
    heap_.reserve(std::max(heap_.capacity(), expected / 4));
  }

  /// The predicted final count (thesis 6.5). Mixed MLE/CCS phase: eq. 6.1, NT_c · q_t /
  /// q(K) for the worst triangle K of the heap (never below NT_c). Frontal phase, whose heap
  /// holds only the front (so its root says little about the rest): the good triangles
  /// count as they are and the bad ones by eq. 6.2, their metric area over S_M(K_I).
  double predictFinal(double worst) const {
    const double current = static_cast<double>(tri_.numTriangles());
    if (frontal_) return current - static_cast<double>(badCount_) + badArea_ / kIdealTriangleArea;
    if (!(worst > 0)) return current;
    return std::max(current, current * opt_.qualityThreshold / worst);
  }

  /// Bookkeeping of the bad triangles' metric area (predictFinal): count() after an
  /// evaluation, uncount() before a triangle is removed or re-evaluated.
  void count(TriId t) {
    if (isAccepted(t) || !std::isfinite(area_[t])) return;
    badArea_ += area_[t];
    ++badCount_;
    counted_[t] = 1;
  }
  void uncount(TriId t) {
    if (!counted_[t]) return;
    badArea_ -= area_[t];
    --badCount_;
    counted_[t] = 0;
  }

  void push(TriId t, double q) {
    queued_[t] = stamp_[t];
    heap_.push_back({q, t.index, stamp_[t]});
    std::push_heap(heap_.begin(), heap_.end(), LowerPriority());
  }

  /// q(K) with M at the centroid (stored for the insertion point), lowered to 0.95 q_t
  /// for a too long unconstrained edge.
  double evaluate(TriId t) {
    const std::uint32_t* tv = tri_.triVertices(t);
    const Vec2 &a = tri_.point(VertexId(tv[0])), &b = tri_.point(VertexId(tv[1])), &c = tri_.point(VertexId(tv[2]));
    const Mat2 m = metricAt(cs_, (a + b + c) / 3.0);
    triMetric_[t] = m;
    double q = triangleQuality(m, a, b, c);
    if (opt_.lift && !opt_.lift->upright(tri_, t)) q = 0;  // turned over on the surface
    quality_[t] = q;
    area_[t] = metricArea(m, a, b, c);
    if (q < opt_.qualityThreshold) return q;
    const double maxLen = opt_.maxEdgeMetricLength;
    for (int i = 0; i < 3; ++i) {
      if (tri_.isConstrained(t, i)) continue;
      const VertexId x(tv[kNext[i]]), y(tv[kPrev[i]]);
      const Vec2 e = tri_.point(y) - tri_.point(x);
      const double len = 0.5 * ((vertexMetric_[x] * e).norm() + (vertexMetric_[y] * e).norm());
      if (len > maxLen) return quality_[t] = 0.95 * opt_.qualityThreshold;
    }
    return q;
  }

  bool isQueued(TriId t) const { return queued_[t] == stamp_[t]; }
  bool isAccepted(TriId t) const { return quality_[t] >= opt_.qualityThreshold; }

  /// The front edge of the bad triangle t (frontal phase): a contour or hull edge, or one
  /// shared with an accepted triangle; the longest in t's metric when several; -1 if none.
  int frontEdge(TriId t) const {
    const std::uint32_t* tv = tri_.triVertices(t);
    const Mat2& m = triMetric_[t];
    int best = -1;
    double bestLen = -1;
    for (int i = 0; i < 3; ++i) {
      const TriId n = tri_.neighbour(t, i);
      if (!tri_.isConstrained(t, i) && n.valid() && !isAccepted(n)) continue;
      const double len = (m * (tri_.point(VertexId(tv[kPrev[i]])) - tri_.point(VertexId(tv[kNext[i]])))).squaredNorm();
      if (len > bestLen) {
        bestLen = len;
        best = i;
      }
    }
    return best;
  }

  /// Frontal phase: the frontal point of K on its front edge (FrontalPoint.h), in the
  /// metric at the edge's midpoint; false when K has no front edge or the point is
  /// unusable (not found by the walk, refused or cancelled by the rules).
  bool refineFrontal(TriId k) {
    const int e = frontEdge(k);
    if (e < 0) return false;
    const std::uint32_t* tv = tri_.triVertices(k);
    const Vec2 a = tri_.point(VertexId(tv[kNext[e]])), b = tri_.point(VertexId(tv[kPrev[e]]));
    const Vec2 c = tri_.point(VertexId(tv[e]));
    Vec2 p;
    if (!frontalPoint(metricAt(cs_, 0.5 * (a + b)), a, b, c, p)) return false;
    const VisibleLocation loc = locateVisible(tri_, k, p, opt_.maxWalkSteps);
    if (!loc.found) return false;
    if (!insertAt(k, p, loc.tri)) return false;
    ++stats_.frontal;
    return true;
  }

  /// Chooses, checks and inserts the point for K; false when cancelled.
  bool refine(TriId k, double q) {
    if (frontal_ && refineFrontal(k)) return true;
    const std::uint32_t* tv = tri_.triVertices(k);
    const Vec2 a = tri_.point(VertexId(tv[0])), b = tri_.point(VertexId(tv[1])), c = tri_.point(VertexId(tv[2]));
    const Mat2 m = triMetric_[k];
    Vec2 p;
    TriId start = k;
    bool mle = q < opt_.mleToCcsQuality;
    if (!mle) {
      if (!metricCircumcenter(m, a, b, c, p)) {
        mle = true;
      } else {
        const VisibleLocation loc = locateVisible(tri_, k, p, opt_.maxWalkSteps);
        if (loc.found) {
          start = loc.tri;
        } else {
          mle = true;
          ++stats_.ccsFallbacks;
        }
      }
    }
    if (mle && !longestEdgeMidpoint(k, m, p)) {
      ++stats_.cancelBoundaryEdge;
      return false;
    }
    if (!insertAt(k, p, start)) return false;
    ++(mle ? stats_.mle : stats_.ccs);
    return true;
  }

  /// Plans the insertion of p for K (walk from start), applies the cancellation rules,
  /// inserts and re-evaluates the changed triangles; false (mesh unchanged) when refused
  /// or cancelled.
  bool insertAt(TriId k, const Vec2& p, TriId start) {
    const Mat2 mp = metricAt(cs_, p);
    const bool guarded = opt_.lift && opt_.lift->active();
    const UprightFan fan(guarded ? opt_.lift : nullptr, p);
    const auto plan_ = [&](const NewTriangleTest* extra) {
      return opt_.innerAngles ? planInsertion(tri_, p, innerAnglesConflict(), start, extra)
                              : planInsertion(tri_, p, mp, start, extra);
    };
    InsertPlan plan = plan_(nullptr);
    // The fold guard: where the cavity is properly upright, the new triangles must be too
    // (re-planned with the guard as part of the star-shape pruning). A cavity holding a
    // folded or untested triangle (a placeholder of the coarse triangulation: around a pole
    // no single point splits it into upright triangles) may be replaced as it is: its
    // folded triangles are refined first (q = 0) until the region is upright.
    if (guarded && plan.status == InsertStatus::Inserted && !fanUpright(fan) && cavityUpright()) {
      plan = plan_(&fan);
      if (plan.status != InsertStatus::Inserted) ++stats_.cancelFold;
    }
    if (plan.status != InsertStatus::Inserted) {
      ++stats_.cancelRefused;
      return false;
    }
    if (!acceptCavity(k, p, mp)) return false;
    for (const TriId t : tri_.workspace().cavity) uncount(t);
    const InsertResult r = applyInsertion(tri_, plan);
    if (guarded) opt_.lift->remember(r.vertex, fan.point());
    vertexMetric_[r.vertex] = mp;
    ++stats_.inserted;
    const std::vector<TriId>& created = tri_.workspace().created;
    if (!opt_.innerAngles) {
      changed_.assign(created.begin(), created.end());
      reevaluateAll(changed_);
      return true;
    }
    changed_.assign(created.begin(), created.end());
    const PlaneTransform tr(mp);
    if (tr.orientation() != 0) {
      const std::size_t n = changed_.size();
      swapStart_.assign(changed_.begin(), changed_.end());
      stats_.swaps += innerAngleSwaps(tri_, swapStart_, tr, opt_.maxSwapsPerPoint, swapStack_, changed_);
      if (changed_.size() > n) {
        std::sort(changed_.begin(), changed_.end());
        changed_.erase(std::unique(changed_.begin(), changed_.end()), changed_.end());
      }
    }
    reevaluateAll(changed_);
    return true;
  }

  /// New or changed triangles: their heap entries are invalidated and each is evaluated;
  /// then the bad ones are pushed (in the frontal phase only those on the front), and the
  /// accepted ones put their bad, unqueued neighbours on the front. Two passes, so every
  /// changed triangle has its new quality before a neighbour looks at it.
  void reevaluateAll(const std::vector<TriId>& changed) {
    for (const TriId t : changed) {
      if (!tri_.isAlive(t)) continue;
      uncount(t);
      ++stamp_[t];
      evaluate(t);
      count(t);
    }
    for (const TriId t : changed) {
      if (!tri_.isAlive(t)) continue;
      if (!isAccepted(t)) {
        if (!isQueued(t) && (!frontal_ || frontEdge(t) >= 0)) push(t, quality_[t]);
        continue;
      }
      if (!frontal_) continue;
      for (int i = 0; i < 3; ++i) {
        const TriId n = tri_.neighbour(t, i);
        if (n.valid() && !isAccepted(n) && !isQueued(n)) push(n, quality_[n]);
      }
    }
  }

  /// Every triangle (p, a, b) over the planned cavity's boundary is upright.
  bool fanUpright(const UprightFan& fan) const {
    for (const CavityEdge& e : tri_.workspace().boundary)
      if (!fan.accept(tri_, e.a, e.b)) return false;
    return true;
  }

  /// Every triangle of the planned cavity is tested and upright.
  bool cavityUpright() const {
    for (const TriId t : tri_.workspace().cavity)
      if (opt_.lift->pose(tri_, t) != SurfaceLift::Pose::Upright) return false;
    return true;
  }

  /// The middle of the longest edge of K in m; false when that edge is constrained.
  bool longestEdgeMidpoint(TriId k, const Mat2& m, Vec2& p) const {
    const std::uint32_t* tv = tri_.triVertices(k);
    int best = 0;
    double bestLen = -1;
    for (int i = 0; i < 3; ++i) {
      const double len = (m * (tri_.point(VertexId(tv[kPrev[i]])) - tri_.point(VertexId(tv[kNext[i]])))).squaredNorm();
      if (len > bestLen) {
        bestLen = len;
        best = i;
      }
    }
    if (tri_.isConstrained(k, best)) return false;
    p = 0.5 * (tri_.point(VertexId(tv[kNext[best]])) + tri_.point(VertexId(tv[kPrev[best]])));
    return true;
  }

  /// The cancellation rules on the planned cavity (in the triangulation's workspace).
  bool acceptCavity(TriId k, const Vec2& p, const Mat2& mp) {
    const Workspace2d& ws = tri_.workspace();
    // (Inner-angles insertion: the cavity is the containing triangle, the rule does not apply.)
    if (!opt_.innerAngles && std::find(ws.cavity.begin(), ws.cavity.end(), k) == ws.cavity.end()) {
      ++stats_.cancelMetricJump;
      return false;
    }
    const double minV2 = opt_.minVertexDistance * opt_.minVertexDistance;
    for (const CavityEdge& e : ws.boundary) {
      const Vec2& x = tri_.point(e.a);
      if ((mp * (p - x)).squaredNorm() < minV2) {
        ++stats_.cancelNearVertex;
        return false;
      }
      if ((e.constrained || !e.outside.valid()) &&
          segmentDistance(mp, p, x, tri_.point(e.b)) < opt_.minContourDistance) {
        ++stats_.cancelNearContour;
        return false;
      }
    }
    return true;
  }

  Triangulation2d& tri_;
  const ControlSpace2d& cs_;
  const RefineOptions& opt_;
  VertexAttribute<Mat2> vertexMetric_;
  TriangleAttribute<Mat2> triMetric_;
  TriangleAttribute<std::uint32_t> stamp_;
  static constexpr std::uint32_t kNotQueued = 0xFFFFFFFFu;
  TriangleAttribute<double> quality_;          ///< last q(K) (with the long-edge rule)
  TriangleAttribute<std::uint32_t> queued_;    ///< stamp_ when last pushed
  TriangleAttribute<double> area_;             ///< metric area at the last evaluation
  TriangleAttribute<std::uint8_t> counted_;    ///< area_ is in badArea_
  double badArea_ = 0;
  std::size_t badCount_ = 0;
  bool frontal_;                               ///< in the frontal phase
  std::vector<HeapEntry> heap_;
  std::vector<TriId> changed_, swapStart_;    // inner-angles mode scratch
  std::vector<std::uint32_t> swapStack_;
  RefineStats stats_;
};

}  // namespace

RefineStats refineFace(Triangulation2d& tri, const ControlSpace2d& cs, const RefineOptions& options) {
  Refiner refiner(tri, cs, options);
  return refiner.run();
}

}  // namespace aniso::face
