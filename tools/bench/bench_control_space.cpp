// Control space benchmarks (sec. 3.2.4, 3.3, table 3.1):
//   BM_QuadtreeQuery / BM_OctreeQuery     getMetric() at random points of an adapted tree
//                                         (counters: leaves, control vertices, depth);
//   BM_QuadtreeQueryCached                the same along a random walk with the proximity
//                                         cache of sec. 3.2.4 item 3 (counter: hit rate);
//   BM_QuadtreeBuild / BM_OctreeBuild     building the tree from a continuous source plus
//                                         gradation smoothing, for ε_δ = 10, 1, 0.1 (the
//                                         values of table 3.1; counter NPc = control vertices);
//   BM_Analytic2dQuery / ..Mutex          a muParser control space with per-thread parsers
//                                         (the implementation) against one parser set
//                                         behind a mutex, on 1 and 2 threads;
//   BM_Mesh2dQuery / BM_Mesh3dQuery       getMetric() of the background meshes (sec. 3.4)
//                                         built from the same sources as the query trees,
//                                         with the interpolation set A_s / A_t / A_o as
//                                         argument 0 / 1 / 2 (counters: control vertices,
//                                         elements); A_t also on 2 threads;
//   BM_Mesh2dQueryCached                  the random walk of BM_QuadtreeQueryCached;
//   BM_Mesh2dBuild / BM_Mesh3dBuild       continuous source plus smoothing for ε_δ = 10,
//                                         1, 0.1, as the tree builds (counter NPc);
//   BM_Mesh2dPointSources / ..3d..        build time against the number of control
//                                         vertices: N random point sources inserted while
//                                         fresh, then initialization (extrapolation) and
//                                         smoothing.
#include <benchmark/benchmark.h>
#include <muParser.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <mutex>
#include <numbers>
#include <random>
#include <vector>

#include "mesher/control/CSAnalytic2d.h"
#include "mesher/control/CSAnalytic3d.h"
#include "mesher/control/CSMesh2d.h"
#include "mesher/control/CSMesh3d.h"
#include "mesher/control/CSOctree3d.h"
#include "mesher/control/CSQuadtree2d.h"
#include "mesher/control/MetricQueryCache.h"

using namespace aniso;

namespace {

/// The two test domains: a field with turning directions and a sharp size minimum (a
/// boundary-layer-like band along a circle / sphere), smooth everywhere, and point
/// sources along a closed curve (like contour-curvature sources, sec. 3.5.1).
struct Dim2 {
  using V = Vec2;
  using Analytic = CSAnalytic2d;
  static Box2 box() {
    Box2 b;
    b.add(Vec2(0, 0));
    b.add(Vec2(1, 1));
    return b;
  }
  static Metric2d field(const Vec2& p) {
    const Vec2 d = p - Vec2(0.5, 0.5);
    const double band = std::abs(d.norm() - 0.3);
    const double h1 = 0.0002 + 0.05 * band * band + 0.01 * band;
    return Metric2d::fromAngle(std::atan2(d.y(), d.x()), h1, std::min(10 * h1, 0.05));
  }
  static constexpr int kCurveSources = 20000;
  static std::pair<Vec2, Metric2d> curveSource(double t) {
    return {Vec2(0.5 + 0.35 * std::cos(t), 0.5 + 0.2 * std::sin(2 * t)), Metric2d::fromAngle(t, 0.0002, 0.002)};
  }
};

struct Dim3 {
  using V = Vec3;
  using Analytic = CSAnalytic3d;
  static Box3 box() {
    Box3 b;
    b.add(Vec3::Zero());
    b.add(Vec3::Ones());
    return b;
  }
  static Metric3d field(const Vec3& p) {
    const Vec3 d = p - Vec3(0.5, 0.5, 0.5);
    const double band = std::abs(d.norm() - 0.3);
    const double h1 = 0.002 + 0.1 * band * band + 0.02 * band;
    const Vec3 n = d.norm() > 1e-9 ? Vec3(d.normalized()) : Vec3(Vec3::UnitZ());
    const Vec3 t = n.unitOrthogonal();
    return Metric3d::fromDirections(n, t, n.cross(t), h1, std::min(5 * h1, 0.1), std::min(5 * h1, 0.1));
  }
  static constexpr int kCurveSources = 5000;
  static std::pair<Vec3, Metric3d> curveSource(double t) {
    return {Vec3(0.5 + 0.3 * std::cos(t), 0.5 + 0.3 * std::sin(t), 0.5 + 0.1 * std::sin(3 * t)),
            Metric3d::isotropic(0.001)};
  }
};

SizingParameters withEpsDelta(double eps) {
  SizingParameters p;
  p.metricDifferenceEps = eps;
  return p;
}

/// A control space of dimension D (a tree or a background mesh, built with `args`) with
/// the continuous field, the curve's point sources and gradation smoothing.
template <class CS, class D, class... Args>
CS withCurveSources(Args&&... args) {
  CS cs(D::box(), SizingParameters{}, std::forward<Args>(args)...);
  cs.setContinuousSource(typename D::Analytic(D::box(), D::field));
  for (int i = 0; i < D::kCurveSources; ++i) {
    const auto [p, m] = D::curveSource(2 * std::numbers::pi * i / D::kCurveSources);
    cs.insertDiscreteSource(p, m);
  }
  cs.smoothGradation(4.0);
  return cs;
}

template <class V>
std::vector<V> randomPoints(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<V> pts(n);
  for (V& p : pts)
    for (int k = 0; k < p.size(); ++k) p(k) = u(rng);
  return pts;
}

/// getMetric() at random points (a different sequence per thread).
template <class D, class CS>
void queryLoop(benchmark::State& state, const CS& cs, unsigned seed) {
  const std::vector<typename D::V> pts = randomPoints<typename D::V>(1 << 14, seed + state.thread_index());
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(cs.getMetric(pts[i++ & (pts.size() - 1)]));
  state.SetItemsProcessed(state.iterations());
  state.counters["NPc"] = benchmark::Counter(double(cs.controlVertexCount()), benchmark::Counter::kAvgThreads);
}

/// getMetric() through the proximity cache along a random walk with steps of about a
/// hundredth of the local element size.
template <class CS>
void cachedWalk(benchmark::State& state, const CS& cs) {
  std::mt19937 rng(3);
  std::normal_distribution<double> step(0, 1);
  std::vector<Vec2> walk(1 << 14);
  Vec2 p(0.5, 0.2);
  for (Vec2& w : walk) {
    const double h = cs.getMetric(p).sizing.axes().lengths(0);
    p = (p + 0.01 * h * Vec2(step(rng), step(rng))).cwiseMax(Vec2::Zero()).cwiseMin(Vec2::Ones());
    w = p;
  }
  MetricQueryCache2d cache(0.05);
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(cache.get(cs, walk[i++ & (walk.size() - 1)]));
  state.SetItemsProcessed(state.iterations());
  state.counters["hitRate"] = double(cache.hits()) / double(cache.hits() + cache.misses());
}

void countVertices(benchmark::State& state, std::size_t vertices) {
  state.counters["NPc"] = double(vertices);
  state.counters["NPc_per_s"] = benchmark::Counter(double(vertices) * double(state.iterations()), benchmark::Counter::kIsRate);
}

/// Continuous source plus gradation smoothing with ε_δ = range(0) / 100.
template <class CS, class D>
void buildLoop(benchmark::State& state) {
  const double eps = state.range(0) / 100.0;
  const typename D::Analytic source(D::box(), D::field);
  std::size_t vertices = 0;
  for (auto _ : state) {
    CS cs(D::box(), withEpsDelta(eps));
    cs.setContinuousSource(source);
    cs.smoothGradation(4.0);
    vertices = cs.controlVertexCount();
  }
  state.counters["eps_delta"] = eps;
  countVertices(state, vertices);
}

/// range(0) random point sources inserted while fresh, then initialization and smoothing.
template <class CS, class D>
void pointSourcesLoop(benchmark::State& state, unsigned seed) {
  const std::vector<typename D::V> pts = randomPoints<typename D::V>(static_cast<int>(state.range(0)), seed);
  std::size_t vertices = 0;
  for (auto _ : state) {
    CS cs(D::box(), SizingParameters{});
    for (const auto& p : pts) cs.insertDiscreteSource(p, D::field(p));
    cs.initializeControlVertices();
    cs.smoothGradation(4.0);
    vertices = cs.controlVertexCount();
  }
  countVertices(state, vertices);
}

// ---- trees (sec. 3.2–3.3) ----

const CSQuadtree2d& quadtree() {
  static const CSQuadtree2d cs = withCurveSources<CSQuadtree2d, Dim2>();
  return cs;
}

const CSOctree3d& octree() {
  static const CSOctree3d cs = withCurveSources<CSOctree3d, Dim3>();
  return cs;
}

template <class CS>
void treeCounters(benchmark::State& state, const CS& cs) {
  state.counters["leaves"] = benchmark::Counter(double(cs.leafCount()), benchmark::Counter::kAvgThreads);
  state.counters["depth"] = benchmark::Counter(cs.depth(), benchmark::Counter::kAvgThreads);
}

void BM_QuadtreeQuery(benchmark::State& state) {
  queryLoop<Dim2>(state, quadtree(), 1);
  treeCounters(state, quadtree());
}
BENCHMARK(BM_QuadtreeQuery)->Threads(1)->Threads(2)->UseRealTime();

void BM_OctreeQuery(benchmark::State& state) {
  queryLoop<Dim3>(state, octree(), 7);
  treeCounters(state, octree());
}
BENCHMARK(BM_OctreeQuery)->Threads(1)->Threads(2)->UseRealTime();

void BM_QuadtreeQueryCached(benchmark::State& state) { cachedWalk(state, quadtree()); }
BENCHMARK(BM_QuadtreeQueryCached);

void BM_QuadtreeBuild(benchmark::State& state) { buildLoop<CSQuadtree2d, Dim2>(state); }
BENCHMARK(BM_QuadtreeBuild)->Arg(1000)->Arg(100)->Arg(10)->Unit(benchmark::kMillisecond);

void BM_OctreeBuild(benchmark::State& state) { buildLoop<CSOctree3d, Dim3>(state); }
BENCHMARK(BM_OctreeBuild)->Arg(1000)->Arg(100)->Arg(10)->Unit(benchmark::kMillisecond);

// ---- analytic control space: per-thread parsers against a mutex ----

const char* const kAlpha = "pi/6 + u*v";
const char* const kH1 = "0.01 + 0.02*sin(3*u)^2";
const char* const kH2 = "0.0101 - 0.005*u";

void BM_Analytic2dQuery(benchmark::State& state) {
  static const CSAnalytic2d cs(Dim2::box(), kAlpha, kH1, kH2);
  const std::vector<Vec2> pts = randomPoints<Vec2>(1 << 12, 11 + state.thread_index());
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(cs.getMetric(pts[i++ & (pts.size() - 1)]));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Analytic2dQuery)->Threads(1)->Threads(2)->UseRealTime();

/// The alternative design: one parser set shared by all threads behind a mutex.
struct LockedExpression {
  std::mutex mutex;
  double u = 0, v = 0;
  mu::Parser p[3];
  LockedExpression() {
    const char* exprs[3] = {kAlpha, kH1, kH2};
    for (int i = 0; i < 3; ++i) {
      p[i].DefineVar("u", &u);
      p[i].DefineVar("v", &v);
      p[i].DefineConst("pi", std::numbers::pi);
      p[i].SetExpr(exprs[i]);
    }
  }
  Metric2d operator()(const Vec2& x) {
    std::lock_guard<std::mutex> lock(mutex);
    u = x.x();
    v = x.y();
    return Metric2d::fromAngle(p[0].Eval(), p[1].Eval(), p[2].Eval());
  }
};

void BM_Analytic2dMutex(benchmark::State& state) {
  static LockedExpression expr;
  static const CSAnalytic2d cs(Dim2::box(), [](const Vec2& x) { return expr(x); });
  const std::vector<Vec2> pts = randomPoints<Vec2>(1 << 12, 11 + state.thread_index());
  std::size_t i = 0;
  for (auto _ : state) benchmark::DoNotOptimize(cs.getMetric(pts[i++ & (pts.size() - 1)]));
  state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_Analytic2dMutex)->Threads(1)->Threads(2)->UseRealTime();

// ---- background meshes (sec. 3.4) ----

BackgroundMeshOptions meshOptions(int method) {
  BackgroundMeshOptions o;
  o.interpolation = static_cast<BackgroundInterpolation>(method);
  return o;
}

/// The background mesh of the same sources as the query tree, per interpolation set
/// (the adaptation to the continuous source depends on it), built once.
template <class CS, class D>
const CS& backgroundMesh(int method) {
  static const std::array<CS, 3> all = {withCurveSources<CS, D>(meshOptions(0)), withCurveSources<CS, D>(meshOptions(1)),
                                        withCurveSources<CS, D>(meshOptions(2))};
  return all[static_cast<std::size_t>(std::clamp(method, 0, 2))];
}

void BM_Mesh2dQuery(benchmark::State& state) {
  const CSMesh2d& cs = backgroundMesh<CSMesh2d, Dim2>(static_cast<int>(state.range(0)));
  queryLoop<Dim2>(state, cs, 1);
  state.counters["elements"] = benchmark::Counter(double(cs.triangleCount()), benchmark::Counter::kAvgThreads);
}
BENCHMARK(BM_Mesh2dQuery)->Arg(0)->Arg(1)->Arg(2)->UseRealTime();
BENCHMARK(BM_Mesh2dQuery)->Arg(1)->Threads(2)->UseRealTime();

void BM_Mesh3dQuery(benchmark::State& state) {
  const CSMesh3d& cs = backgroundMesh<CSMesh3d, Dim3>(static_cast<int>(state.range(0)));
  queryLoop<Dim3>(state, cs, 7);
  state.counters["elements"] = benchmark::Counter(double(cs.tetCount()), benchmark::Counter::kAvgThreads);
}
BENCHMARK(BM_Mesh3dQuery)->Arg(0)->Arg(1)->Arg(2)->UseRealTime();
BENCHMARK(BM_Mesh3dQuery)->Arg(1)->Threads(2)->UseRealTime();

void BM_Mesh2dQueryCached(benchmark::State& state) { cachedWalk(state, backgroundMesh<CSMesh2d, Dim2>(1)); }
BENCHMARK(BM_Mesh2dQueryCached);

void BM_Mesh2dBuild(benchmark::State& state) { buildLoop<CSMesh2d, Dim2>(state); }
BENCHMARK(BM_Mesh2dBuild)->Arg(1000)->Arg(100)->Arg(10)->Unit(benchmark::kMillisecond);

void BM_Mesh3dBuild(benchmark::State& state) { buildLoop<CSMesh3d, Dim3>(state); }
BENCHMARK(BM_Mesh3dBuild)->Arg(1000)->Arg(100)->Arg(10)->Unit(benchmark::kMillisecond);

void BM_Mesh2dPointSources(benchmark::State& state) { pointSourcesLoop<CSMesh2d, Dim2>(state, 13); }
BENCHMARK(BM_Mesh2dPointSources)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

void BM_Mesh3dPointSources(benchmark::State& state) { pointSourcesLoop<CSMesh3d, Dim3>(state, 17); }
BENCHMARK(BM_Mesh3dPointSources)->Arg(1000)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace
