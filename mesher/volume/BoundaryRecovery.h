#pragma once
// Constraining of the boundary triangulation (thesis sec. 5.4, table 5.3): every edge and
// face of the solid's boundary mesh made present in the tetrahedralization, each phase
// recovering edges first, then faces, and repeated while it makes progress:
//   phase 1  PIPE-REDUCTION (PipeReduction.h): flips only;
//   phase 2  INTERIOR-CAVITY (CavityRecovery.h): the tets crossing a missing patch are
//            retriangulated as stars around points strictly INSIDE the solid (or around
//            existing vertices), then pipe reduction again.
// No Steiner point is ever put on the boundary (the surface mesh is shared by the solids
// of an assembly and must stay as it is). Present boundary faces are marked constrained
// as soon as they are present, and present boundary edges are never flipped away.
// A solid whose missing edges cross present boundary entities (its boundary mesh
// intersects itself, BoundaryCrossing.h) is not recovered at all: it is returned at once
// (unless pastSelfCrossings: the last resort recovers what it can around the crossings).
// Pipe reduction is not tried again on an entity whose pipe (the entities crossing it) is
// the same as when it last failed: flips alone gave up on that configuration.
// Entities left missing are returned, naming the CAD face (1-based) they lie on.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "mesher/core/Cancel.h"
#include "mesher/volume/BoundaryTriangulation.h"
#include "mesher/volume/PipeReduction.h"

namespace aniso {

struct RecoveryOptions {
  int maxChangesPerEntity = 64;  ///< kept flips per entity and round (pipe reduction)
  int maxRounds = 10;            ///< rounds per phase (a round ends the phase when it makes no progress)
  /// Phase 2 ends after this many rounds in a row that leave no fewer entities missing than
  /// the best round so far, even when they add points (a point that helps makes an entity
  /// present within a round or two; those that do not only make the next rounds longer).
  int maxStalledRounds = 2;
  bool interiorPoints = true;    ///< phase 2 (interior Steiner points)
  /// When the boundary mesh intersects itself: recover the other entities all the same
  /// (the crossing ones stay missing; VolumeMesher's last resort, CarveAroundHoles.h).
  bool pastSelfCrossings = false;
  /// Checked every round (Cancel.h); null: never stops.
  const CancelToken* cancel = nullptr;
};

struct RecoveryStats {
  static constexpr int kPhases = 2;
  long long edges = 0, faces = 0;                ///< boundary entities of the solid
  long long missingEdges = 0, missingFaces = 0;  ///< missing after the triangulation
  std::array<long long, kPhases> edgesRecovered{}, facesRecovered{};
  long long steinerPoints = 0;  ///< points inserted inside the solid
  volume::FlipCounters flips;
  void merge(const RecoveryStats& o);
};

struct RecoveryFailure {
  int face = -1;  ///< 0-based model face of the entity
  std::string what;
  std::vector<int> nodes;  ///< surface-mesh nodes of the missing edge (2) or triangle (3)
};

struct RecoveryResult {
  RecoveryStats stats;
  /// Empty when every edge and face is present. When the boundary mesh intersects itself
  /// (BoundaryCrossing.h): the missing edges that cross a present boundary entity, each
  /// followed by the entity it crosses, found before any recovery is tried.
  std::vector<RecoveryFailure> left;
  bool selfCrossing = false;  ///< the boundary mesh intersects itself (left starts with the crossings)
};

/// Recovers the boundary `bt.boundary` in `bt.tets` (kernel from triangulateBoundary). On
/// return every present boundary face carries the constrained bit; the Steiner points of
/// phase 2 lie strictly inside the solid (on the material side of the boundary triangles
/// around them, CavityRecovery.h).
RecoveryResult recoverBoundary(BoundaryTriangulation& bt, const RecoveryOptions& options = {});

}  // namespace aniso
