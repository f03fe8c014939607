#pragma once
// repairSurface — the surface repair stage, the same for surface and volume meshes
// (issue 16; mesher/pipeline/Pipeline.h runs it after every surface meshing, the volume
// mesher after every round of boundary splits): the caps and sub-tolerance edges first
// (SurfaceSlivers.h: merged and flipped within `tolerance`), then the folds
// (UnfoldSurface.h: flips inside a face, FoldRegion.h), then the slivers once more when
// the folds were mended (kept when that leaves no more folds). Both keep a closed oriented
// surface closed, oriented and conforming; nodes left in no triangle stay in the node
// array. Runs on meshes of linear triangles only (no quads, no mid nodes): on any other
// mesh it changes nothing. Deterministic.
#include <vector>

#include "mesher/model/Model.h"
#include "mesher/surface/SurfaceMesh.h"

namespace aniso {

struct SurfaceRepairStats {
  int nodesMerged = 0;   ///< SurfaceSlivers.h merges
  int capsFlipped = 0;   ///< SurfaceSlivers.h cap flips
  int foldsRepaired = 0; ///< folded edges mended (UnfoldSurface.h)
  int foldsLeft = 0;     ///< folded edges no flip or region mended
  std::vector<int> facesChanged;  ///< 0-based model faces whose triangles changed (may repeat)

  void add(const SurfaceRepairStats& o);
};

/// Repairs `mesh` of `model` in place (see above); `tolerance` bounds how far the surface
/// moves (the volume mesher's kSurfaceSliverTolerance times h_min). Nodes from index
/// `keepFrom` on (>= 0) are not merged away (mendSurfaceSlivers).
SurfaceRepairStats repairSurface(const Model& model, double tolerance, SurfaceMesh& mesh, int keepFrom = -1);

}  // namespace aniso
