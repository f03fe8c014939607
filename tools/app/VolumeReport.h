#pragma once
// The volume part of the run report (--report, dim 3): counts, the recovery statistics of
// thesis table 5.4 (missing edges and faces after the boundary triangulation, recovered
// per phase), one entry per solid (status, tetrahedra, volume, times, statistics). The solids'
// problems are the pipeline's (mesher/pipeline/RunProblems.h).
#include "io/Report.h"
#include "mesher/model/Model.h"
#include "mesher/volume/VolumeMesher.h"

namespace aniso::app {

void fillVolumeReport(const Model& model, const VolumeMeshResult& vr, io::Report& report);

}  // namespace aniso::app
