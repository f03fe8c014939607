#pragma once
// MeshResult — what meshModel (Pipeline.h) returns: the mesh (the surface's, and for dim 3
// the volume's), every problem by CAD entity (mesher/core/Problem.h), the decisions of the
// outer loop's stages and the data a report is made of. Plain data: the report's format is
// the caller's (io/Report).
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "mesher/core/Problem.h"
#include "mesher/highorder/Order2.h"
#include "mesher/pipeline/SurfaceMesher.h"
#include "mesher/volume/SurfaceGeometry.h"
#include "mesher/volume/SurfaceRepair.h"
#include "mesher/volume/VolumeMesher.h"

namespace aniso {

/// One decision of a stage of the pipeline, in the order they were taken, e.g.
/// {"proximity", "round 1 kept", "12 faces refined, 3400 triangles predicted"}.
struct StageDecision {
  std::string stage;     ///< "model", "surface", "proximity", "volume", "fallback", "coarse-solids", "order2"
  std::string decision;  ///< what was decided
  std::string reason;    ///< why, with the numbers
};

/// Alg. 3.3's proximity rounds (VolumeStages.h) as they ended.
struct ProximityOutcome {
  int rounds = 0;                 ///< surfaces meshed finer and kept (0 after the fallback)
  std::size_t facesRefined = 0;   ///< thin faces refined by the kept rounds (failed solids not counted)
  std::size_t thinTrianglesLeft = 0;
  double predictedTriangles = 0;  ///< of the last round considered
  double budgetFactor = 1;        ///< sourcesWithinBudget's factor of the last round scaled
  /// (0-based face, size asked: the thickness found, times budgetFactor when scaled) of
  /// every source of the kept rounds, by round then face.
  std::vector<std::pair<int, double>> refined;
  double seconds = 0;             ///< spent in rounds, fallback and coarse-solid retry
};

/// The coarse-solid retry (CoarseSolids.h) as it ended.
struct CoarseSolidOutcome {
  int solids = 0;            ///< coarse solids found
  bool refinedKept = false;  ///< the finer surface and its volume replaced the first
};

/// Where a run that produced no mesh stopped.
enum class PipelineStop {
  None,     ///< a mesh was made (possibly degraded)
  Model,    ///< the model's topology is unusable: nothing was meshed
  Surface,  ///< no face could be meshed
  Volume,   ///< no solid could be meshed
};

struct MeshResult {
  int dim = 3;
  PipelineStop stop = PipelineStop::None;
  /// Every problem: the model's (grading), then the final surface's, then the volume's.
  std::vector<Problem> problems;
  SurfaceMeshResult surface;  ///< the surface kept (the first, or a finer one of a stage), repaired
  SurfaceRepairStats surfaceRepair;  ///< what the repair stage did to it (SurfaceStage.h)
  SurfaceGeometryCheck surfaceCheck;  ///< its geometric postcondition after the repair
  VolumeMeshResult volume;    ///< dim 3 (empty for dim 2 and when stopped before it)
  bool volumeRan = false;     ///< dim 3 and the volume stages ran
  ProximityOutcome proximity;
  CoarseSolidOutcome coarse;
  std::optional<Order2Stats> order2;  ///< order 2 only
  std::vector<StageDecision> decisions;
  /// Phase times in seconds in the order they ran: the first surface's phases, the volume's
  /// (summed over solids), "order2".
  std::vector<std::pair<std::string, double>> times;

  bool meshed() const { return stop == PipelineStop::None; }
};

}  // namespace aniso
