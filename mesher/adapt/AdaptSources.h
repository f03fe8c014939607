#pragma once
// adaptSources — a solver's field as discrete point sources of a mesh request (issue 19;
// thesis 3.3.1 "Introducing discrete data", 3.5 "User control space"): the field's
// Hessians (recoverHessian) become the Lp metric (lpMetric) scaled to a vertex count or an
// error and clamped to the request's [hmin, hmax] and γ_a; every node of the solver's mesh
// becomes a SizingPoint carrying its metric, which the mesher intersects with the geometric
// sizing (curvature, proximity): the CAD stays approximated. For a volume the metric is
// kVolumeLengthFactor finer, since a volume's tets are that much longer than the surface
// triangles its sizes are given for (VolumeControlSpace.h).
#include <cstddef>
#include <vector>

#include "mesher/adapt/HessianRecovery.h"
#include "mesher/adapt/PatchMesh.h"
#include "mesher/core/Error.h"
#include "mesher/core/MeshOptions.h"
#include "mesher/model/Model.h"
#include "mesher/sizing/UserSizing.h"

namespace aniso {

/// A solver's mesh whose node box misses the model's by more than this fraction of the
/// model's diagonal on a side is not a mesh of that model (a mesh of a curved model lies
/// inside it by its sagitta; a solver moves nothing).
inline constexpr double kCoverTolerance = 0.05;

/// The field is unusable on its mesh (the message names the problem, not the file: the
/// caller, who knows the file, prefixes it).
class FieldError : public InputError {
 public:
  using InputError::InputError;
};

/// What the field gives every mesh of an adaptation: its recovered Hessians and the solver
/// mesh's measures (the count rounds rescale the metric only).
struct FieldHessians {
  std::vector<Mat3> hessians;
  std::vector<double> measures;
  std::vector<Vec3> normals;
  std::vector<BoundaryFacet> boundary;
};

/// `values`: one per node of `from`.
FieldHessians fieldHessians(const PatchMesh& from, const std::vector<double>& values, HessianMethod method);

/// The metric asked of the field: scaled to `targetVertices` (> 0) or to the Lp error
/// `error` (> 0), in the Lp norm p = `norm`.
struct AdaptMetricAsk {
  double norm = 2;
  double targetVertices = 0;
  double error = 0;
};

/// What one call made: for the report.
struct AdaptSourcesRecord {
  std::size_t sources = 0;    ///< point sources added (the solver mesh's nodes in a cell)
  double predictedNodes = 0;  ///< the metric's vertex count (LpMetric.h)
  double predictedError = 0;
  bool limited = false;       ///< the ask was out of reach within [hmin, hmax]
  double hmin = 0, hmax = 0, anisotropy = 1;
  double targetVertices = 0;  ///< the ask's (0 when scaled to an error)
};

/// Adds to `user` one point source per node of `from` used by a cell. `options`: the
/// request's (dim 2 or 3 resolved; its sizing gives hmin, hmax and γ_a). Throws FieldError
/// when `from` does not cover `model` or the field gives no metric (a constant field
/// scaled to an error).
AdaptSourcesRecord addAdaptSources(const Model& model, const PatchMesh& from, const FieldHessians& field,
                                   const AdaptMetricAsk& ask, const MeshOptions& options, UserSizing& user);

}  // namespace aniso
