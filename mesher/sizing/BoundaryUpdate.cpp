#include "mesher/sizing/BoundaryUpdate.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "mesher/core/Segment.h"
#include "mesher/metric/MetricComparison.h"
#include "mesher/metric/MetricIntersection.h"
#include "mesher/sizing/BoundaryGaps.h"

namespace aniso {
namespace {

/// A thin face's h_min is at least this many times its CAD tolerance: below, two edges are
/// the same curve as far as the CAD model knows.
constexpr double kToleranceFactor = 10.0;
/// On a thin face (h_min_f = its width) gaps down to half its h_min_f are resolved.
constexpr double kThinFaceResolvedGap = 0.5;
/// Gap sources along a boundary segment at most this many gap widths apart, and at most
/// kMaxGapSamples of them per segment. SlenderSurface.brep (a planar strip 0.4 um wide and
/// 10 mm long) at the defaults: its first segments are 1 mm long; with sources at their
/// ends and midpoints only, three rounds left it with needles (mean ratio 0.849); with these
/// it meshes in one. Surface meshes only (BoundaryUpdateOptions::gapsAlongSegments): in an
/// assembly the strips are narrow side faces (NEO's 60 um label), and resolving them along
/// their whole length grew NEO's surface mesh by 20 % (562 k -> 674 k triangles, --dim 2);
/// its 3D census run with them stopped at the 300 s limit on a loaded machine.
constexpr double kGapSourceSpacing = 2.0;
constexpr int kMaxGapSamples = 4096;

/// Would intersecting the control space's metric at `at` with m change it by more than
/// eps (δ_M)? Sources that change nothing are not inserted, so the rounds of alg. 3.1 stop.
bool wouldChange(const CSAdaptive2d& cs, const Vec2& at, const Metric2d& m, double eps) {
  const Metric2d current = cs.getMetric(at).sizing;
  return metricDifference(intersect(current, m), current) > eps;
}

/// Sources are collected first and inserted after every test, so that all tests of a round
/// see the same control space.
struct Source {
  Vec2 at;
  Metric2d m;
};

/// The segments before and after segment i along its loop (i itself on a loop of one).
std::pair<int, int> loopNeighbours(const BoundarySegments& bs, int i) {
  const std::size_t loop = static_cast<std::size_t>(bs.segments[static_cast<std::size_t>(i)].loop);
  const int first = bs.loopFirst[loop], last = bs.loopFirst[loop + 1] - 1;
  return {i > first ? i - 1 : last, i < last ? i + 1 : first};
}

/// The sources of one gap (BoundaryUpdate.h): elements no longer than the gap across it, at
/// most γ_a times that along it, at the segment's midpoint and the nearest point of the
/// other side (the gap found there) and at the segment's ends (their distance to that other
/// segment: a tapering gap is narrower at one end); none where the gap is narrower than
/// `narrowest`.
void addGapSources(const CSAdaptive2d& cs, const BoundarySegments& bs, const BoundaryGap& g, double narrowest,
                   double hMin, bool along, const SizingParameters& params, std::vector<Source>& sources,
                   BoundaryUpdateStats& stats) {
  const BoundarySegment& s = bs.segments[g.segment];
  const Mat2 mp = cs.getMetric(g.at).parameterization;
  // The width at a sample is its distance to the other side: to `other` and the segments
  // next to it along its loop. To `other` alone, a sample beyond its end measured the
  // offset along the gap too: a strip 1 um wide whose sides' nodes do not face each other
  // (KiCad's pin sockets, 1 um steps round the pin holes) had a width of a few um at
  // the nodes, above the narrowest resolved gap, and the sources there graded h_min into
  // the faces around (needles, 0.24 deg tets).
  // The neighbours of `other` that are `segment` or next to it are this side, not the other
  // (a sharp corner: the two sides meet at its tip).
  const auto [prev, next] = loopNeighbours(bs, g.other);
  const auto [mine0, mine1] = loopNeighbours(bs, g.segment);
  const auto atEnd = [&](const Vec2& e) {
    double d = 1e300;
    for (const int k : {prev, g.other, next}) {
      if (k != g.other && (k == g.segment || k == mine0 || k == mine1)) continue;
      const BoundarySegment& o = bs.segments[static_cast<std::size_t>(k)];
      d = std::min(d, (mp * (closestPointOnSegment<Vec2>(e, o.a, o.b) - e)).norm());
    }
    return d;
  };
  std::vector<std::pair<Vec2, double>> samples = {
      {s.a, atEnd(s.a)}, {Vec2(0.5 * (s.a + s.b)), g.width()}, {s.b, atEnd(s.b)}, {g.at, g.width()}};
  // A segment much longer than the gap (a first discretization at h_max along a strip):
  // samples every kGapSourceSpacing gap widths along it, or the sizes between the samples
  // grade up again and the rounds of alg. 3.1 end before the strip is resolved.
  const double spacing = kGapSourceSpacing * std::max(g.width(), hMin);
  const int n = along ? static_cast<int>(std::min<double>(kMaxGapSamples, std::ceil(s.length / spacing))) : 0;
  for (int k = 1; k < n; ++k) {
    const Vec2 p = s.a + (s.b - s.a) * (static_cast<double>(k) / n);
    samples.push_back({p, atEnd(p)});
  }
  const double angle = std::atan2(g.across.y(), g.across.x());
  bool inserted = false, narrow = false;
  for (const auto& [p, width] : samples) {
    if (width < narrowest) {
      narrow = true;
      continue;
    }
    const double h = std::max(width, hMin);
    const Metric2d m = Metric2d::fromAngle(angle, h, h * params.anisotropy);
    if (!wouldChange(cs, p, m, params.metricDifferenceEps)) continue;
    sources.push_back({p, m});
    inserted = true;
  }
  stats.gaps += inserted;
  stats.unresolvedGaps += narrow;
}

}  // namespace

double faceMinSize(double width, const BoundaryUpdateOptions& o) {
  if (!o.thinFaces || !(width < o.thinFaceWidth * o.hMin)) return o.hMin;
  const double floor = std::min(o.hMin, std::max(o.thinFaceRatio * o.hMin, kToleranceFactor * o.cadTolerance));
  return std::clamp(width, floor, o.hMin);
}

BoundaryUpdateStats updateFromBoundary(CSAdaptive2d& cs, const FaceBoundary& boundary,
                                       const SizingParameters& params, const BoundaryUpdateOptions& options) {
  BoundaryUpdateStats stats;
  stats.faceMinSize = options.hMin;
  const double lMin = 1.0 / params.adaptLengthMax;  // 1 / l_Mmax
  const BoundarySegments bs = boundarySegments(cs, boundary);
  if (bs.segments.empty()) return stats;
  // the crossing rounds of a volume mesh need no gaps (no thin face: h_min_f is h_min)
  std::vector<BoundaryGap> gaps;
  if (!options.crossingsOnly || options.thinFaces) gaps = findBoundaryGaps(cs, bs, lMin, options.hMin);
  stats.faceMinSize = faceMinSize(thinFaceWidth(bs, gaps, options.hMin), options);

  // A strip: most of its boundary faces another side across a gap.
  double gapLength = 0, total = 0;
  for (const BoundarySegment& sg : bs.segments) total += sg.length;
  for (const BoundaryGap& g : gaps)
    if (g.metricWidth < lMin) gapLength += bs.segments[g.segment].length;
  const bool strip = gapLength > options.stripFraction * total;
  // a volume mesh's strip too narrow to resolve: a step or sliver face of the CAD (see the header)
  const double unresolved = options.resolvedGapRatio * options.hMin;
  const bool step =
      !options.thinFaces && !options.filmRim && strip && thinFaceWidth(bs, gaps, unresolved) < unresolved;
  if ((!options.vicinity && !strip && !(stats.faceMinSize < options.hMin)) || options.crossingsOnly) gaps.clear();
  const double hMin = stats.faceMinSize;
  std::vector<Source> sources;
  for (const BoundarySegment& sg : bs.segments) {
    const Vec2 mid = 0.5 * (sg.a + sg.b);
    if (!(sg.length > 0) || options.crossingsOnly) continue;
    if (step && sg.length < unresolved) {  // its end: no source
      ++stats.stepEnds;
      continue;
    }
    if ((cs.getMetric(mid).transformation() * (sg.b - sg.a)).norm() < lMin) {
      // The segment's ends and midpoint: control elements can be much smaller than a
      // segment in (u, v) (a strip thin in u but long in v), and a single point source would
      // then refine only around itself.
      const Metric2d src = Metric2d::isotropic(std::max(sg.length, hMin));
      if (wouldChange(cs, mid, src, params.metricDifferenceEps)) {
        for (const Vec2& p : {sg.a, mid, sg.b}) sources.push_back({p, src});
        ++stats.shortSegments;
      }
    }
  }
  for (const int c : crossingSegments(bs)) {
    const BoundarySegment& sg = bs.segments[static_cast<std::size_t>(c)];
    const Metric2d src = Metric2d::isotropic(std::max(0.5 * sg.length, hMin));
    const Vec2 mid = 0.5 * (sg.a + sg.b);
    if (!wouldChange(cs, mid, src, params.metricDifferenceEps)) continue;
    for (const Vec2& p : {sg.a, mid, sg.b}) sources.push_back({p, src});
    ++stats.crossings;
  }
  const double narrowest = hMin < options.hMin ? kThinFaceResolvedGap * hMin : options.resolvedGapRatio * hMin;
  for (const BoundaryGap& g : gaps) {
    if (!(g.metricWidth < lMin)) continue;  // found by its real width only: resolved already
    addGapSources(cs, bs, g, narrowest, hMin, options.gapsAlongSegments, params, sources, stats);
  }
  for (const Source& src : sources) cs.insertDiscreteSource(src.at, src.m);
  return stats;
}

}  // namespace aniso
