#pragma once
// meshModel — the whole meshing process of a model, the one call a program makes (thesis
// 3.5, alg. 3.3; STYLE.md §13). Stages, each bounded, their decisions recorded in the result:
//   1 model grading (RunProblems.h): Model::check() as problems; unusable faces are left
//     out, a model with nothing usable stops here (PipelineStop::Model);
//   2 the surface mesh and its repair (SurfaceStage.h), the same for 2D and 3D; no face
//     meshed stops here (PipelineStop::Surface); the kept surface's geometric
//     postcondition (SurfaceGeometry.h) is in result.surfaceCheck;
//   3 dim 3: the volume stages (VolumeStages.h): alg. 3.3's proximity rounds, the final
//     volume, the fallback to the first surface, the coarse-solid retry; no solid meshed
//     stops here (PipelineStop::Volume);
//   4 order 2 (Order2.h) when asked, on the mesh kept.
// Progress and messages go through mesher/core/Log.h; options.cancel stops the run
// (throws Cancelled). Throws InputError (the element budget cannot be met) and
// MeshingError only for errors that stop everything; entity failures are problems.
// The result is identical for any number of threads.
#include "mesher/model/Model.h"
#include "mesher/pipeline/MeshRequest.h"
#include "mesher/pipeline/MeshResult.h"

namespace aniso {

MeshResult meshModel(const Model& model, const MeshRequest& request);

}  // namespace aniso
