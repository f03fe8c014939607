#include "mesher/volume/SurfaceRepair.h"

#include "mesher/core/Log.h"
#include "mesher/volume/SurfaceSlivers.h"
#include "mesher/volume/UnfoldSurface.h"

namespace aniso {

void SurfaceRepairStats::add(const SurfaceRepairStats& o) {
  nodesMerged += o.nodesMerged;
  capsFlipped += o.capsFlipped;
  foldsRepaired += o.foldsRepaired;
  foldsLeft = o.foldsLeft;  // of the latest repair: what is left in the mesh
  facesChanged.insert(facesChanged.end(), o.facesChanged.begin(), o.facesChanged.end());
}

SurfaceRepairStats repairSurface(const Model& model, double tolerance, SurfaceMesh& mesh, int keepFrom) {
  SurfaceRepairStats r;
  if (!mesh.quads.empty() || !mesh.triangleMid.empty() || !mesh.quadMid.empty()) return r;
  const SurfaceSliverStats s = mendSurfaceSlivers(mesh, tolerance, &model, keepFrom);
  r.nodesMerged = s.nodesMerged;
  r.capsFlipped = s.capsFlipped;
  r.facesChanged = s.facesChanged;
  if (s.nodesMerged + s.capsFlipped > 0)
    logDebug("surface repair: " + std::to_string(s.nodesMerged) + " nodes merged, " + std::to_string(s.capsFlipped) +
             " caps flipped on " + std::to_string(s.facesChanged.size()) + " faces");
  const UnfoldStats u = unfoldSurface(mesh);
  r.foldsRepaired = u.foldedBefore - u.foldedAfter;
  r.foldsLeft = u.foldedAfter;
  r.facesChanged.insert(r.facesChanged.end(), u.facesChanged.begin(), u.facesChanged.end());
  if (u.foldedBefore > 0)
    logDebug("surface repair: " + std::to_string(u.foldedBefore) + " folded edges, " + std::to_string(u.flips) +
             " flips, " + std::to_string(u.regions) + " regions (" + std::to_string(u.nodesDropped) +
             " nodes dropped), " + std::to_string(u.foldedAfter) + " left");
  // a fold region re-triangulated across a narrow face can leave its sub-tolerance edges
  // and caps again: mended once more, kept only when it leaves no more folds
  if (u.flips + u.regions > 0) {
    SurfaceMesh again = mesh;
    const SurfaceSliverStats s2 = mendSurfaceSlivers(again, tolerance, &model, keepFrom);
    if (s2.nodesMerged + s2.capsFlipped > 0 && countFoldedEdges(again) <= u.foldedAfter) {
      mesh = std::move(again);
      r.nodesMerged += s2.nodesMerged;
      r.capsFlipped += s2.capsFlipped;
      r.facesChanged.insert(r.facesChanged.end(), s2.facesChanged.begin(), s2.facesChanged.end());
    }
  }
  return r;
}

}  // namespace aniso
