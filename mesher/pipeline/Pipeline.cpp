#include "mesher/pipeline/Pipeline.h"

#include <chrono>
#include <string>

#include "mesher/pipeline/MeshGrade.h"
#include "mesher/pipeline/RunProblems.h"
#include "mesher/pipeline/SurfaceStage.h"
#include "mesher/pipeline/VolumeStages.h"
#include "mesher/sizing/VolumeChordBound.h"

namespace aniso {

int resolvedDim(const MeshOptions& options, bool modelHasSolids) {
  if (options.dim != 0) return options.dim;
  return modelHasSolids ? 3 : 2;
}

namespace {

/// Stage 4: order 2 on the mesh kept (Order2.h).
template <class Mesh>
void elevate(const Model& model, Mesh& mesh, MeshResult& r) {
  const auto t = std::chrono::steady_clock::now();
  r.order2 = elevateToOrder2(model, mesh);
  r.times.emplace_back("order2", std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count());
}

void append(std::vector<Problem>& to, std::vector<Problem> from) {
  to.insert(to.end(), std::make_move_iterator(from.begin()), std::make_move_iterator(from.end()));
}

}  // namespace

MeshResult meshModel(const Model& model, const MeshRequest& request) {
  MeshResult r;
  r.dim = resolvedDim(request.options, !model.solids.empty());
  // stage 1: CAD defects graded; unusable faces are left out
  ModelGrade grade = gradeModel(model);
  r.problems = std::move(grade.problems);
  if (!grade.usable) {
    r.stop = PipelineStop::Model;
    r.decisions.push_back({"model", "nothing meshed", "an unusable solid or shell, or no usable face"});
    return r;
  }
  // stage 2: the surface
  SurfaceMesherInput sin;
  sin.model = &model;
  sin.options = request.options;
  sin.analytic = request.analytic;
  sin.user = &request.user;
  sin.skipFaces = std::move(grade.skipFaces);
  sin.chordDeviation = volumeChordDeviation(model, request.options.sizing.chordDeviationRel * model.diagonal());
  r.surface = meshRepairedSurface(sin, &r.surfaceRepair, surfaceRepairApplies(sin, r.dim));
  r.times = r.surface.times;
  if (r.surface.mesh.triangles.empty() && r.surface.mesh.quads.empty()) {
    append(r.problems, surfaceProblems(model, r.surface));
    r.stop = PipelineStop::Surface;
    r.decisions.push_back({"surface", "nothing meshed", "no face could be meshed"});
    return r;
  }
  // stage 3: the volume
  if (r.dim == 3) {
    VolumeStagesInput vin;
    vin.model = &model;
    vin.surface = sin;
    vin.user = &request.user;
    vin.options = request.options;
    runVolumeStages(vin, r);
    r.volumeRan = true;
    for (const auto& p : r.volume.times) r.times.push_back(p);
  }
  append(r.problems, surfaceProblems(model, r.surface));
  r.surfaceCheck = checkSurfaceGeometry(model, r.surface.mesh);
  append(r.problems, gradeSurfaceGeometry(model, r.surfaceCheck));
  const SurfaceRepairStats& rep = r.surfaceRepair;
  std::string findings;
  for (const std::string& m : r.surfaceCheck.messages()) findings += (findings.empty() ? "" : ", ") + m;
  r.decisions.push_back({"surface-repair", r.surfaceCheck.ok() ? "surface valid" : "shortcomings left",
                         std::to_string(rep.nodesMerged) + " nodes merged, " + std::to_string(rep.capsFlipped) +
                             " caps flipped, " + std::to_string(rep.foldsRepaired) + " folded edges mended" +
                             (findings.empty() ? "" : "; " + findings)});
  if (r.volumeRan) {
    append(r.problems, volumeProblems(model, r.volume));
    if (r.volume.mesh.tets.empty()) {
      r.stop = PipelineStop::Volume;
      return r;
    }
    append(r.problems, gradeVolumeMesh(model, r.volume, request.options.sizing.anisotropy <= 1));
  } else {
    append(r.problems, gradeSurfaceMesh(r.surface.mesh, request.options.sizing.anisotropy <= 1 && !request.analytic));
  }
  // stage 4: order 2
  if (request.options.order == 2) {
    if (r.volumeRan) elevate(model, r.volume.mesh, r);
    else elevate(model, r.surface.mesh, r);
  }
  return r;
}

}  // namespace aniso
