#include "mesher/surface/face/Refinement.h"

#include "mesher/core/Segment.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "mesher/delaunay/Attributes2d.h"
#include "mesher/delaunay/InsertPoint.h"
#include "mesher/delaunay/Workspace2d.h"
#include "mesher/surface/face/FaceMetric.h"
#include "mesher/surface/face/InnerAngleSwaps.h"
#include "mesher/surface/face/VisibleWalk.h"

namespace aniso::face {

using namespace del2d;

namespace {

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
        stamp_(tri, 0u) {}

  RefineStats run() {
    initialise();
    if (opt_.onPrediction) opt_.onPrediction(stats_.predictedTriangles);
    std::size_t pops = 0;
    while (!heap_.empty()) {
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
    for (std::uint32_t k = 0; k < tri_.triangleSlots(); ++k) {
      const TriId t(k);
      if (!tri_.isAlive(t)) continue;
      const double q = evaluate(t);
      if (q < opt_.qualityThreshold) push(t, q);
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

  /// Eq. 6.1: NT_c · q_t / q(K) for the worst triangle K of the heap (never below NT_c).
  double predictFinal(double worst) const {
    const double current = static_cast<double>(tri_.numTriangles());
    if (!(worst > 0)) return current;
    return std::max(current, current * opt_.qualityThreshold / worst);
  }

  void push(TriId t, double q) {
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
    if (q < opt_.qualityThreshold) return q;
    const double maxLen = opt_.maxEdgeMetricLength;
    for (int i = 0; i < 3; ++i) {
      if (tri_.isConstrained(t, i)) continue;
      const VertexId x(tv[kNext[i]]), y(tv[kPrev[i]]);
      const Vec2 e = tri_.point(y) - tri_.point(x);
      const double len = 0.5 * ((vertexMetric_[x] * e).norm() + (vertexMetric_[y] * e).norm());
      if (len > maxLen) return 0.95 * opt_.qualityThreshold;
    }
    return q;
  }

  /// Chooses, checks and inserts the point for K; false when cancelled.
  bool refine(TriId k, double q) {
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
    const Mat2 mp = metricAt(cs_, p);
    const InsertPlan plan = opt_.innerAngles ? planInsertion(tri_, p, innerAnglesConflict(), start)
                                             : planInsertion(tri_, p, mp, start);
    if (plan.status != InsertStatus::Inserted) {
      ++stats_.cancelRefused;
      return false;
    }
    if (!acceptCavity(k, p, mp)) return false;
    const InsertResult r = applyInsertion(tri_, plan);
    vertexMetric_[r.vertex] = mp;
    ++stats_.inserted;
    ++(mle ? stats_.mle : stats_.ccs);
    const std::vector<TriId>& created = tri_.workspace().created;
    if (!opt_.innerAngles) {
      for (const TriId t : created) reevaluate(t);
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
    for (const TriId t : changed_)
      if (tri_.isAlive(t)) reevaluate(t);
    return true;
  }

  /// A new or changed triangle: invalidates its heap entries, pushes it when bad.
  void reevaluate(TriId t) {
    ++stamp_[t];
    const double q = evaluate(t);
    if (q < opt_.qualityThreshold) push(t, q);
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
