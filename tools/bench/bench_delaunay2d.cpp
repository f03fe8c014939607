// Benchmark of the 2D triangulation kernel (mesher/delaunay): insertion rate for random
// points in a square with the identity metric (and one anisotropic constant M), points
// per second and bytes per triangle. Variants: BRIO + Hilbert order with walks from the
// last triangle (default) or from the seeding quadtree (thesis sec. 4.4.1), insertion only
// on pre-sorted input, and the thesis' input order with quadtree seeding.
#include <benchmark/benchmark.h>

#include <Eigen/Geometry>
#include <random>
#include <vector>

#include "mesher/delaunay/Delaunay2d.h"
#include "mesher/delaunay/SpatialSort.h"

namespace {

using aniso::Mat2;
using aniso::Vec2;
using namespace aniso::del2d;

const std::vector<Vec2>& randomPoints(std::size_t n) {
  static std::vector<Vec2> pts;
  if (pts.size() != n) {
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    pts.resize(n);
    for (Vec2& p : pts) p = Vec2(u(rng), u(rng));
  }
  return pts;
}

void run(benchmark::State& state, const std::vector<Vec2>& pts, const TriangulateOptions& opt) {
  TriangulateResult r;
  std::size_t triangles = 0, bytes = 0;
  for (auto _ : state) {
    const Triangulation2d tri = triangulatePoints(pts, opt, &r);
    triangles = tri.numTriangles();
    bytes = tri.memoryBytes();
    benchmark::DoNotOptimize(triangles);
  }
  state.counters["points/s"] =
      benchmark::Counter(static_cast<double>(pts.size()), benchmark::Counter::kIsIterationInvariantRate);
  state.counters["bytes/tri"] = static_cast<double>(bytes) / static_cast<double>(triangles);
  state.counters["steps/pt"] = static_cast<double>(r.walkSteps) / static_cast<double>(pts.size());
  state.counters["refused"] = static_cast<double>(r.refused);
}

void BM_Delaunay2dBrioLastTriangle(benchmark::State& state) {
  run(state, randomPoints(static_cast<std::size_t>(state.range(0))), TriangulateOptions{});
}
BENCHMARK(BM_Delaunay2dBrioLastTriangle)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->MinTime(2.0);

void BM_Delaunay2dBrioSeedQuadtree(benchmark::State& state) {
  TriangulateOptions opt;
  opt.walkStart = WalkStart::SeedQuadtree;
  run(state, randomPoints(static_cast<std::size_t>(state.range(0))), opt);
}
BENCHMARK(BM_Delaunay2dBrioSeedQuadtree)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->MinTime(2.0);

// Insertion only: the points already in Hilbert order, no sorting inside the timing.
void BM_Delaunay2dPresortedInsertOnly(benchmark::State& state) {
  const std::vector<Vec2>& raw = randomPoints(static_cast<std::size_t>(state.range(0)));
  const std::vector<std::uint32_t> order = hilbertOrder(raw);
  std::vector<Vec2> pts;
  pts.reserve(raw.size());
  for (std::uint32_t k : order) pts.push_back(raw[k]);
  TriangulateOptions opt;
  opt.spatialSort = false;
  run(state, pts, opt);
}
BENCHMARK(BM_Delaunay2dPresortedInsertOnly)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->MinTime(2.0);

// Thesis variant: random input order, walks seeded by the quadtree.
void BM_Delaunay2dInputOrderSeedQuadtree(benchmark::State& state) {
  TriangulateOptions opt;
  opt.spatialSort = false;
  opt.walkStart = WalkStart::SeedQuadtree;
  run(state, randomPoints(static_cast<std::size_t>(state.range(0))), opt);
}
BENCHMARK(BM_Delaunay2dInputOrderSeedQuadtree)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->MinTime(2.0);

// Constant anisotropic metric (100:1 at 30°): every in-circle test on M·x.
void BM_Delaunay2dAnisotropic(benchmark::State& state) {
  TriangulateOptions opt;
  const Eigen::Rotation2Dd r(0.5236);
  opt.transform = r.toRotationMatrix() * Eigen::Vector2d(100.0, 1.0).asDiagonal() * r.toRotationMatrix().transpose();
  run(state, randomPoints(static_cast<std::size_t>(state.range(0))), opt);
}
BENCHMARK(BM_Delaunay2dAnisotropic)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->MinTime(2.0);

}  // namespace
