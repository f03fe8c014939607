// Benchmark of the volume mesher's refinement and improvement (thesis sec. 5.5–5.6,
// mesher/volume/VolumeRefinement.h, VolumeImprovement.h): a unit cube at a uniform size
// h (issue 5 §2 expects about 500k tets at h = 0.02, Gmsh HXT's count — its inner edges
// average 1.45 h; the tets are made in M_v, edges f·h (VolumeControlSpace.h, f =
// kVolumeLengthFactor), as the CLI does: the unit mesh of sec. 5.5 in M itself gives about
// 1.3 M; Gmsh HXT reaches mean ratio 0.815 and a smallest
// dihedral angle of 14° there). The boundary is the Delaunay triangulation of
// points on the cube's surface at spacing h (tests/unit/volume_refine_fixture.h), built
// outside the timed region. Counters: tets, tets/s (refine + improve), kernel bytes/tet
// (TetMesh capacities), peak RSS of the process during the benchmark per final tet, and the referee's measures
// (mean ratio average, smallest dihedral angle, meshq's order-dependent dihedral minimum).
// Two size fields: the analytic uniform one, and the octree control space that
// buildVolumeControlSpace makes from the surface (its construction is timed).
#include <benchmark/benchmark.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <string>

#include "mesher/control/CSAnalytic3d.h"
#include "mesher/volume/TetQuality.h"
#include "mesher/volume/VolumeControlSpace.h"
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

/// Resets the peak RSS to the current RSS (Linux: "5" to /proc/self/clear_refs), so each
/// benchmark reports its own peak.
void resetPeakRss() { std::ofstream("/proc/self/clear_refs") << "5"; }

void run(benchmark::State& state, bool octree) {
  resetPeakRss();
  const int n = static_cast<int>(state.range(0));
  const double h = 1.0 / n;
  Box3 box;
  box.add(Vec3(0, 0, 0));
  box.add(Vec3(1, 1, 1));
  const VolumeMetricSpace uniform(
      std::make_shared<CSAnalytic3d>(box, [h](const Vec3&) { return Metric3d::isotropic(h); }));
  SolidTetMesh s;
  VolumeRefineStats rs;
  VolumeImproveStats is;
  std::shared_ptr<ControlSpace3d> cs;
  for (auto _ : state) {
    state.PauseTiming();
    std::set<testing::Triple> boundary;
    s = testing::cubeSolid(n, boundary);
    const testing::CubeSurface surface = testing::cubeSurface(s, boundary);
    state.ResumeTiming();
    if (octree) {
      SizingParameters sizing;
      sizing.hmax = h;
      cs = std::make_shared<VolumeMetricSpace>(buildVolumeControlSpace(surface.model, surface.surface, 0, sizing, nullptr));
    }
    const ControlSpace3d& field = octree ? *cs : static_cast<const ControlSpace3d&>(uniform);
    rs = refineVolume(s, field);
    is = improveVolume(s, field);
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
  state.counters["referee_dihedral_min"] = q.refereeMinDihedral;
  state.counters["slivers<5deg"] = static_cast<double>(q.belowDihedral);
  state.counters["inserted"] = static_cast<double>(rs.inserted);
  state.counters["flips"] = static_cast<double>(is.flips23 + is.flips32 + is.flips44);
}

/// Uniform analytic size h = 1/n (no control-space cost).
void BM_VolumeCubeUniform(benchmark::State& state) { run(state, false); }
/// The control space built from the surface (buildVolumeControlSpace, octree), h_max = 1/n.
void BM_VolumeCubeOctree(benchmark::State& state) { run(state, true); }
BENCHMARK(BM_VolumeCubeUniform)->Arg(20)->Arg(50)->Unit(benchmark::kMillisecond)->Iterations(1);
BENCHMARK(BM_VolumeCubeOctree)->Arg(20)->Arg(50)->Unit(benchmark::kMillisecond)->Iterations(1);

}  // namespace
