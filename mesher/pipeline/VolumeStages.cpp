#include "mesher/pipeline/VolumeStages.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <optional>

#include "mesher/core/Cancel.h"
#include "mesher/core/Log.h"
#include "mesher/pipeline/SurfaceStage.h"
#include "mesher/pipeline/UndoRefinement.h"
#include "mesher/volume/CoarseSolids.h"
#include "mesher/volume/SolidMeshCache.h"
#include "mesher/volume/ThinBoundary.h"

namespace aniso {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

std::string num(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}

/// Faces the surface mesher could not mesh (a finer surface must not lose more of them).
std::size_t failedFaces(const SurfaceMeshResult& sr) {
  return static_cast<std::size_t>(
      std::count_if(sr.faces.begin(), sr.faces.end(), [](const FaceOutcome& o) { return !o.problems.empty(); }));
}

/// The first surface and its repair, kept for the fallback once a finer one replaces it.
struct FirstSurface {
  SurfaceMeshResult surface;
  SurfaceRepairStats repair;
};

void decide(MeshResult& r, std::string stage, std::string decision, std::string reason) {
  r.decisions.push_back({std::move(stage), std::move(decision), std::move(reason)});
}

/// Logs (info) what one meshing took, by phase.
void logTimes(const std::string& what, double seconds, const std::vector<std::pair<std::string, double>>& phases) {
  std::string text = what + ": " + num(seconds) + " s";
  for (const auto& [phase, t] : phases) text += ", " + phase + " " + num(t);
  logInfo(text);
}

/// The repaired surface of the stages' input with `sizing` in place of the user's.
SurfaceMeshResult surfaceWith(const VolumeStagesInput& in, const UserSizing& sizing, SurfaceRepairStats& repair) {
  SurfaceMesherInput sin = in.surface;
  sin.user = &sizing;
  return meshRepairedSurface(sin, &repair);
}

/// Stage 1. True when result.volume is final (no solid thin); false when the surface kept
/// needs its final volume. `sizing` collects the sources of the kept rounds; `first`
/// receives the first surface when a finer one replaces it.
bool proximityRounds(const VolumeStagesInput& in, VolumeMesherInput& vin, UserSizing& sizing,
                     std::optional<FirstSurface>& first, MeshResult& r) {
  ProximityOutcome& px = r.proximity;
  const double hmin = in.options.sizing.hminFor(in.model->diagonal());
  // one budget for all rounds, from the first surface: rounds must not compound
  const double firstTriangles = static_cast<double>(r.surface.mesh.triangles.size());
  const double budget = kMaxProximityGrowth * firstTriangles;
  std::optional<bool> thinWhole;
  for (int round = 1; round <= kMaxProximityRounds; ++round) {
    const std::string name = "round " + std::to_string(round);
    vin.surface = &r.surface.mesh;
    vin.stopWhenThin = true;
    const auto tr = Clock::now();
    r.volume = {};  // the previous round's tetrahedra are not needed while meshing again (peak memory)
    r.volume = meshVolumes(vin);
    logTimes("proximity " + name + ": volume", since(tr), r.volume.times);
    if (r.volume.solidsDeferred > 0)
      logInfo("proximity " + name + ": " + std::to_string(r.volume.solidsDeferred) +
              " solids touching a thin one wait for the finer surface (recovered, not refined)");
    std::vector<SizingSource> failed = failedSolidSources(*in.model, r.surface.mesh, r.volume.solids);
    if (r.volume.thin.empty() && failed.empty()) {
      decide(r, "proximity", name + ": not needed", "no solid thinner than its boundary triangles");
      return true;
    }
    if (px.rounds > 0 && !failed.empty()) {
      // a solid that failed on the finer surface: its refinement is undone, the other
      // solids keep theirs (rather than all falling back to the first surface)
      const std::size_t undone =
          undoRefinementOfFailed(*in.model, in.user->sources.size(), r.volume.solids, sizing, r.proximity);
      if (undone > 0) {
        SurfaceRepairStats repair;
        SurfaceMeshResult coarser = surfaceWith(in, sizing, repair);
        px.seconds += since(tr);
        if (failedFaces(coarser) > failedFaces(r.surface)) {
          decide(r, "proximity", name + ": undoing dropped", "the surface left more faces unmeshed");
          return false;
        }
        r.surface = std::move(coarser);
        r.surfaceRepair = repair;
        decide(r, "proximity", name + ": refinement undone",
               std::to_string(undone) + " sources of solids that failed on the finer surface");
        continue;  // the next round (or the final volume) meshes the volumes again
      }
    }
    const double triangles = static_cast<double>(r.surface.mesh.triangles.size());
    // thin as a whole or in places: decided on the first surface (a finer surface of a part
    // refined at a few times its thickness is mostly thin spots again)
    if (!thinWhole) thinWhole = static_cast<double>(r.volume.thin.size()) >= kThinWholeShare * triangles;
    const bool whole = *thinWhole;
    if (const double failedLimit = std::min(budget, kThinInPlacesGrowth * firstTriangles);
        !failed.empty() && !whole && failedLimit > triangles && predictedTriangles(r.surface.mesh, failed) > budget) {
      // a solid left without tetrahedra whose refinement asks more than the budget is refined
      // as far as the thin-in-places budget allows, not left so (KiCad's Finder 40.11 relay
      // at the defaults: its 0.5 mm housing asked 35 times the surface)
      double factor = 1;
      failed = sourcesWithinBudget(r.surface.mesh, failed, failedLimit, &factor);
      decide(r, "proximity", name + ": failed solids' sources scaled to the budget", "factor " + num(factor));
    }
    std::vector<std::pair<int, double>> faceSizes;
    double roundFactor = 1;  // this round's budget scaling of the sizes
    std::vector<SizingSource> sources = thinSources(r.volume.thin, hmin, &faceSizes, in.model);
    sources.insert(sources.end(), failed.begin(), failed.end());
    px.predictedTriangles = predictedTriangles(r.surface.mesh, sources);
    std::string notRun = "nothing the minimum size would refine";
    const double thinLimit = std::min(budget, std::max(kThinInPlacesGrowth * firstTriangles, kThinInPlacesTriangles));
    if (px.predictedTriangles > thinLimit && !whole) {
      // thin in places: sizes up to kMaxThinAspect times the thickness (flat tetrahedra
      // across, but no slivers) within the smaller budget; when even that does not fit, the
      // thin solids that do, the failed solids first (a solid without tetrahedra weighs
      // more than thin spots left as they are)
      const std::vector<SizingSource> thin(sources.begin(), sources.end() - static_cast<std::ptrdiff_t>(failed.size()));
      const double failedGrowth = failed.empty() ? 0.0 : predictedTriangles(r.surface.mesh, failed) - triangles;
      const double thinBudget = std::min(budget, kThinInPlacesGrowth * firstTriangles) - failedGrowth;
      double factor = 1;
      std::vector<SizingSource> scaled = thinBudget > triangles
                                             ? sourcesWithinBudget(r.surface.mesh, thin, thinBudget, &factor, kMaxThinAspect)
                                             : thin;
      std::size_t groups = 0, kept = 0;
      const std::vector<std::size_t> keep =
          cheapestGroupsWithinBudget(r.surface.mesh, scaled, thinBudget, &groups, &kept);
      sources.clear();
      std::vector<std::pair<int, double>> keptSizes;
      for (const std::size_t i : keep) {
        sources.push_back(scaled[i]);
        keptSizes.push_back(faceSizes[i]);
      }
      faceSizes = std::move(keptSizes);
      roundFactor = px.budgetFactor = factor;
      sources.insert(sources.end(), failed.begin(), failed.end());
      const std::string left = std::to_string(groups - kept) + " of " + std::to_string(groups) + " thin solids left";
      notRun = num(px.predictedTriangles) + " triangles predicted for " + num(triangles) + ", beyond the budget; " + left;
      if (!sources.empty()) {
        px.predictedTriangles = predictedTriangles(r.surface.mesh, sources);
        decide(r, "proximity", name + ": thin in places",
               "sizes " + num(factor) + " x the thickness, " + left +
                   (failed.empty() ? std::string() : "; the failed solids first"));
      }
    }
    if (px.predictedTriangles > budget && kMinProximityGrowth * triangles < budget && whole) {
      sources = sourcesWithinBudget(r.surface.mesh, sources, budget, &px.budgetFactor);
      roundFactor = px.budgetFactor;
      px.predictedTriangles = predictedTriangles(r.surface.mesh, sources);
      decide(r, "proximity", name + ": sources scaled to the budget", "factor " + num(px.budgetFactor));
    }
    const std::string asked = num(px.predictedTriangles) + " triangles predicted for " + num(triangles);
    if (sources.empty() || px.predictedTriangles > budget || px.predictedTriangles < kMinProximityGrowth * triangles) {
      decide(r, "proximity", name + ": not run",
             sources.empty() ? notRun
                             : asked + (px.predictedTriangles > budget ? ", beyond the budget" : ", too little growth"));
      return false;
    }
    sizing.sources.insert(sizing.sources.end(), sources.begin(), sources.end());
    SurfaceRepairStats repair;
    const auto ts = Clock::now();
    SurfaceMeshResult finer = surfaceWith(in, sizing, repair);
    logTimes("proximity " + name + ": surface", since(ts), finer.times);
    px.seconds += since(tr);
    ++px.rounds;
    if (failedFaces(finer) > failedFaces(r.surface)) {
      decide(r, "proximity", name + ": finer surface dropped",
             std::to_string(failedFaces(finer)) + " faces unmeshed, " + std::to_string(failedFaces(r.surface)) + " before");
      return false;
    }
    // a face's source may be several boxes (clear of cusp edges), consecutive: one entry
    faceSizes.erase(std::unique(faceSizes.begin(), faceSizes.end()), faceSizes.end());
    px.facesRefined += faceSizes.size();
    for (const auto& [f, h] : faceSizes) px.refined.push_back({f, h * roundFactor});
    if (!first) first = FirstSurface{std::move(r.surface), r.surfaceRepair};
    r.surface = std::move(finer);
    r.surfaceRepair = repair;
    const std::string failedText = failed.empty() ? std::string()
                                                  : ", " + std::to_string(failed.size()) + " failed solids at " +
                                                        num(kFailedRefine) + " of their mean edge";
    decide(r, "proximity", name + ": finer surface kept",
           std::to_string(faceSizes.size()) + " faces refined" + failedText + ", " + asked);
  }
  return false;
}

/// Stage 4: the coarse-solid retry (CoarseSolids.h).
void coarseSolidRetry(const VolumeStagesInput& in, const VolumeMesherInput& vin, const UserSizing& sizing,
                      MeshResult& r) {
  if (!r.volume.ok()) return;
  const std::vector<SizingSource> coarse = coarseSolidSources(*in.model, r.surface.mesh, r.volume.solids);
  r.coarse.solids = static_cast<int>(coarse.size());
  if (coarse.empty()) return;
  const auto tr = Clock::now();
  UserSizing finerSizing = sizing;
  finerSizing.sources.insert(finerSizing.sources.end(), coarse.begin(), coarse.end());
  const std::string name = std::to_string(coarse.size()) + " coarse solids";
  try {
    SurfaceRepairStats repair;
    SurfaceMeshResult finer = surfaceWith(in, finerSizing, repair);
    if (failedFaces(finer) > failedFaces(r.surface)) {
      decide(r, "coarse-solids", "first mesh kept", name + ": the finer surface left more faces unmeshed");
    } else {
      VolumeMesherInput fin = vin;
      fin.surface = &finer.mesh;
      fin.stopWhenThin = false;
      VolumeMeshResult fvr = meshVolumes(fin);
      const double before = r.volume.quality.meanRatio.mean();
      const std::string ratio = "mean ratio " + num(before) + " -> " + num(fvr.quality.meanRatio.mean());
      if (fvr.ok() && fvr.quality.meanRatio.mean() > before) {
        r.volume = std::move(fvr);
        r.surface = std::move(finer);
        r.surfaceRepair = repair;
        r.coarse.refinedKept = true;
        decide(r, "coarse-solids", "finer mesh kept", name + ", " + ratio);
      } else {
        decide(r, "coarse-solids", "first mesh kept", name + (fvr.ok() ? ", " + ratio : ", the finer volume failed"));
      }
    }
  } catch (const Cancelled&) {
    throw;
  } catch (const MeshingError& e) {
    logWarning(std::string("coarse solids: the finer surface failed (") + e.what() + "); the first mesh is kept");
    decide(r, "coarse-solids", "first mesh kept", name + ": " + e.what());
  }
  r.proximity.seconds += since(tr);
}

}  // namespace

void runVolumeStages(const VolumeStagesInput& in, MeshResult& r) {
  VolumeMesherInput vin;
  vin.model = in.model;
  vin.options = in.options;
  vin.user = in.user;  // the volume follows the finer surface (eq. 3.3) without box sources
  SolidMeshCache cache(in.model->solids.size());  // solids whose boundary a round left unchanged
  vin.cache = &cache;
  UserSizing sizing = *in.user;  // the user's and the proximity sources, for the surface
  std::optional<FirstSurface> first;
  if (!proximityRounds(in, vin, sizing, first, r)) {
    // stage 2: the final volume of the surface kept
    vin.surface = &r.surface.mesh;
    vin.stopWhenThin = false;
    const auto tr = Clock::now();
    r.volume = {};
    r.volume = meshVolumes(vin);
    decide(r, "volume", r.volume.ok() ? "meshed" : "failed",
           (r.proximity.rounds ? "the surface of round " + std::to_string(r.proximity.rounds) : "the first surface") +
               (r.volume.solidsReused ? "; " + std::to_string(r.volume.solidsReused) +
                                            " solids with an unchanged boundary kept as meshed in the round"
                                      : ""));
    // stage 3: a finer surface whose volume failed gives way to the first surface
    if (r.proximity.rounds > 0 && !r.volume.ok()) {
      r.proximity.rounds = 0;
      r.proximity.facesRefined = 0;
      r.proximity.refined.clear();
      if (first) {
        r.surface = std::move(first->surface);
        r.surfaceRepair = first->repair;
        vin.surface = &r.surface.mesh;
        r.volume = meshVolumes(vin);
      }  // else the surface is the first already, its volume made above (deterministic)
      r.proximity.seconds += since(tr);
      decide(r, "fallback", "volume of the first surface", r.volume.ok() ? "meshed" : "failed too");
    }
  }
  coarseSolidRetry(in, vin, sizing, r);
  r.proximity.thinTrianglesLeft = r.volume.thin.size();
}

}  // namespace aniso
