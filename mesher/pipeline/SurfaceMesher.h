#pragma once
// SurfaceMesher — the whole surface meshing process of a model (thesis 3.5.1, ch. 4):
//   1 the initial control space of every face (alg. 3.2, sizing/FaceControlSpace.h), in parallel
//   2 the discretization of every edge, shared by its faces (alg. 4.1)
//   2b the element budget (thesis 6.5, sizing/SurfaceBudget.h): the count the control spaces ask
//     for, against options.maxElements; over it the sizes are floored (and step 2 redone),
//     or, when even h_max cannot fit, InputError with the prediction
//   3 the anisotropic Delaunay mesh of every face (surface/FaceMesher.h), in parallel
//   4 the assembly into one conforming SurfaceMesh, faces in id order
// Faces are independent once their edges are discretized, so steps 1 and 3 run on
// `threads` threads; every result is stored by face index and assembled in order, so the
// output is identical for any number of threads.
#include <optional>
#include <string>
#include <vector>

#include "mesher/control/ControlSpace2d.h"
#include "mesher/core/MeshOptions.h"
#include "mesher/metric/QualityStats.h"
#include "mesher/model/Model.h"
#include "mesher/quad/QuadConversion.h"
#include "mesher/sizing/ElementBudget.h"
#include "mesher/sizing/UserSizing.h"
#include "mesher/surface/FaceMesher.h"
#include "mesher/surface/SurfaceMesh.h"

namespace aniso {

struct SurfaceMesherInput {
  const Model* model = nullptr;
  MeshOptions options;
  const ControlSpace2d* analytic = nullptr;  ///< user 2D sizing (single-face analytic models)
  const UserSizing* user = nullptr;          ///< user 3D sources
  FaceMesherOptions face;
  /// Faces not to mesh (empty, or one flag per face): faces whose CAD topology could not be
  /// used (the caller reports why). Their edges are still discretized for their neighbours.
  std::vector<char> skipFaces;
  /// The chord deviation (absolute, VolumeChordBound.h) when already known for this model
  /// and options (the pipeline's surface rounds share it); unset: computed.
  std::optional<double> chordDeviation;
};

/// Quality in metric space (thesis 2.5) of one face or of the whole mesh: η_M, μ_M and
/// E_K as FaceQuality (surface/improve/FaceQuality.h) measures them.
struct MetricQuality {
  QualityStats eta, mu, ek;
  void merge(const MetricQuality& o) {
    eta.merge(o.eta);
    mu.merge(o.mu);
    ek.merge(o.ek);
  }
};

struct FaceOutcome {
  FaceMeshStats stats;
  MetricQuality quality;
  std::vector<std::string> problems;  ///< empty when the face meshed
  int triangles = 0;
  int quads = 0;
  /// The face coincides with this earlier face (0-based) and took its triangles
  /// (contour/CoincidentFaces.h); −1 otherwise.
  int sharedWith = -1;
  quad::QuadStats quad;  ///< the quad conversion (--quad); quality.mu is then over its edges
};

struct SurfaceMeshResult {
  SurfaceMesh mesh;
  std::vector<FaceOutcome> faces;
  MetricQuality quality;
  std::vector<std::pair<std::string, double>> times;  ///< phase → seconds
  ElementBudget budget;  ///< the prediction before meshing, and the floor it applied (if any)
  bool ok() const;
};

/// Throws InputError when the element budget cannot be met (step 2b), MeshingError only
/// for errors that stop everything; a face that fails (its control space cannot be built,
/// an edge of it cannot be discretized, its boundary loops cannot be chained in (u, v), or
/// its mesher fails) is reported in faces[f].problems and left unmeshed.
SurfaceMeshResult meshSurfaces(const SurfaceMesherInput& in);

}  // namespace aniso
