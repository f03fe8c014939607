// Benchmark of the 3D Delaunay kernel (mesher/delaunay3d): build time for random points
// in a cube with the identity metric, tetrahedra per second and bytes per tetrahedron
// (capacities of the TetMesh arrays). Reference: CGAL ~1.4 M tets/s, TetGen ~1.0 M tets/s.
#include <benchmark/benchmark.h>

#include <random>
#include <vector>

#include "mesher/delaunay3d/Delaunay3d.h"

namespace {

using aniso::Vec3;
using namespace aniso::del3d;

const std::vector<Vec3>& randomPoints(std::size_t n) {
  static std::vector<Vec3> pts;
  if (pts.size() != n) {
    std::mt19937_64 rng(12345);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    pts.resize(n);
    for (Vec3& p : pts) p = Vec3(u(rng), u(rng), u(rng));
  }
  return pts;
}

void report(benchmark::State& state, const TetMesh& mesh, const DelaunayResult& r) {
  const double tets = static_cast<double>(mesh.numTets());
  state.counters["tets"] = tets;
  state.counters["tets/s"] = benchmark::Counter(tets, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["bytes/tet"] = static_cast<double>(mesh.memoryBytes()) / tets;
  state.counters["refused"] = static_cast<double>(r.refused);
}

void BM_Delaunay3dRandomCube(benchmark::State& state) {
  const std::vector<Vec3>& pts = randomPoints(static_cast<std::size_t>(state.range(0)));
  TetMesh mesh;
  DelaunayResult r;
  for (auto _ : state) {
    r = buildDelaunay(mesh, pts);
    benchmark::DoNotOptimize(mesh.numTets());
  }
  report(state, mesh, r);
}
BENCHMARK(BM_Delaunay3dRandomCube)->Arg(100000)->Arg(1000000)->Unit(benchmark::kMillisecond)->MinTime(2.0);

// Thesis variant: input order, walks seeded by the octree of sec. 5.3.2.
void BM_Delaunay3dSeedOctree(benchmark::State& state) {
  const std::vector<Vec3>& pts = randomPoints(static_cast<std::size_t>(state.range(0)));
  DelaunayOptions opt;
  opt.spatialSort = false;
  opt.useSeedOctree = true;
  TetMesh mesh;
  DelaunayResult r;
  for (auto _ : state) {
    r = buildDelaunay(mesh, pts, opt);
    benchmark::DoNotOptimize(mesh.numTets());
  }
  report(state, mesh, r);
}
BENCHMARK(BM_Delaunay3dSeedOctree)->Arg(100000)->Unit(benchmark::kMillisecond);

// A strongly stretched constant metric (in-sphere on M·x).
void BM_Delaunay3dAnisotropic(benchmark::State& state) {
  const std::vector<Vec3>& pts = randomPoints(static_cast<std::size_t>(state.range(0)));
  DelaunayOptions opt;
  opt.transform = Vec3(1.0, 20.0, 3.0).asDiagonal();
  opt.transform(0, 1) = opt.transform(1, 0) = 2.0;
  TetMesh mesh;
  DelaunayResult r;
  for (auto _ : state) {
    r = buildDelaunay(mesh, pts, opt);
    benchmark::DoNotOptimize(mesh.numTets());
  }
  report(state, mesh, r);
}
BENCHMARK(BM_Delaunay3dAnisotropic)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace
