// Benchmark of the volume mesher's refinement and improvement (thesis sec. 5.5–5.6,
// mesher/volume/VolumeRefinement.h, VolumeImprovement.h): a unit cube at a uniform size
// h (issue 5 §2: h = 0.02 gives about 500k tets; Gmsh HXT reaches mean ratio 0.815 and a
// smallest dihedral angle of 14° there). The boundary is the Delaunay triangulation of
// points on the cube's surface at spacing h (tests/unit/volume_refine_fixture.h), built
// outside the timed region. Counters: tets, tets/s (refine + improve), kernel bytes/tet
// (TetMesh capacities), peak RSS of the process per final tet, and the referee's measures
// (mean ratio average, smallest dihedral angle).
#include <benchmark/benchmark.h>

#include <cmath>
#include <fstream>
#include <string>

#include "mesher/control/CSAnalytic3d.h"
#include "mesher/volume/TetQuality.h"
#include "mesher/volume/VolumeImprovement.h"
#include "mesher/volume/VolumeRefinement.h"
#include "tests/unit/volume_refine_fixture.h"

namespace {

using namespace aniso;

/// Peak resident set size of the process in bytes (VmHWM), 0 when unknown.
double peakRss() {
  std::ifstream in("/proc/self/status");
  std::string key;
  while (in >> key) {
    if (key == "VmHWM:") {
      double kb = 0;
      in >> kb;
      return kb * 1024;
    }
    in.ignore(1 << 12, '\n');
  }
  return 0;
}

void BM_VolumeRefineImproveCube(benchmark::State& state) {
  const double h = 1.0 / static_cast<double>(state.range(0));
  Box3 box;
  box.add(Vec3(0, 0, 0));
  box.add(Vec3(1, 1, 1));
  const CSAnalytic3d cs(box, [h](const Vec3&) { return Metric3d::isotropic(h); });
  SolidTetMesh s;
  VolumeRefineStats rs;
  VolumeImproveStats is;
  for (auto _ : state) {
    state.PauseTiming();
    std::set<testing::Triple> boundary;
    s = testing::cubeSolid(static_cast<int>(state.range(0)), boundary);
    state.ResumeTiming();
    rs = refineVolume(s, cs);
    is = improveVolume(s, cs);
    benchmark::DoNotOptimize(s.mesh.numTets());
  }
  TetQualitySummary q;
  accumulateTetQuality(s, nullptr, q);
  const double tets = static_cast<double>(s.mesh.numTets());
  state.counters["tets"] = tets;
  state.counters["tets/s"] = benchmark::Counter(tets, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["kernel_B/tet"] = static_cast<double>(s.mesh.memoryBytes()) / tets;
  state.counters["peakRSS_B/tet"] = peakRss() / tets;
  state.counters["eta_avg"] = q.meanRatio.mean();
  state.counters["eta_min"] = q.meanRatio.min();
  state.counters["dihedral_min"] = q.minDihedral;
  state.counters["slivers<5deg"] = static_cast<double>(q.belowDihedral);
  state.counters["inserted"] = static_cast<double>(rs.inserted);
  state.counters["flips"] = static_cast<double>(is.flips23 + is.flips32 + is.flips44);
}
BENCHMARK(BM_VolumeRefineImproveCube)->Arg(20)->Arg(50)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
