#pragma once
// adaptModel — a model meshed adapted to a solver's field (issue 19): the field's metric
// as point sources (AdaptSources.h) added to the request's sizing, then meshModel
// (Pipeline.h) from the CAD model, so the new boundary nodes lie on the CAD surfaces.
// Asked for a node count, the meshes are made again until the count is met within
// kCountTolerance (at most kMaxCountRounds meshes), the metric rescaled by a secant step on
// log(nodes made) against log(vertices asked of the metric); the rounds stop early when the
// count cannot follow the metric (a measured slope below kCountSlope[0]: thin walls,
// hmin / hmax or curvature bound it) or the metric is already clamped on the side the
// count missed. The mesh returned is the closest to the count asked. Asked for an error,
// one mesh. Deterministic; cancellable through request.mesh.options.cancel.
#include <string>
#include <vector>

#include "mesher/adapt/AdaptSources.h"
#include "mesher/pipeline/MeshRequest.h"
#include "mesher/pipeline/MeshResult.h"

namespace aniso {

/// --target-nodes is met within this fraction when it can be. The Lp metric's prediction
/// (LpMetric.h) is calibrated on uniform metrics; anisotropic fields that vary fast make
/// more nodes, fields the solver's mesh does not resolve fewer (docs/adapt.md).
inline constexpr double kCountTolerance = 0.15;
inline constexpr int kMaxCountRounds = 3;
/// The secant step's slope: below [0] the count does not follow the metric (the rounds
/// stop); the step uses at most [1].
inline constexpr double kCountSlope[2] = {0.2, 1.5};
/// The output's nodes per vertex of an order-2 mesh (mid-side nodes counted, as a solver
/// counts them): a Delaunay tet mesh has ~6.5 edges per vertex (7 nodes per vertex with the
/// boundary's fewer), a triangle mesh 3 (4). Indexed by dimension.
inline constexpr double kQuadraticNodesPerVertex[4] = {1, 1, 4.0, 7.0};

struct AdaptRequest {
  /// The mesh asked for, options.dim resolved to 2 or 3; its user sizing gets the field's
  /// point sources on top of its own.
  MeshRequest mesh;
  double norm = 2;          ///< p of the Lp norm the metric minimises (≥ 1)
  double targetNodes = 0;   ///< the output's node count asked (> 0), or
  double error = 0;         ///< the Lp interpolation error asked (> 0)
};

/// One mesh of the count rounds.
struct AdaptRound {
  double scaled = 0;         ///< the vertex count the metric was scaled to
  double made = 0;           ///< the output's nodes
  bool limitedAway = false;  ///< the metric was clamped on the side the count missed
};

struct AdaptResult {
  MeshResult mesh;              ///< the mesh kept (mesh.meshed() false: the round that failed)
  AdaptSourcesRecord metric;    ///< the kept mesh's metric
  std::vector<AdaptRound> rounds;  ///< every mesh made, in order (one when asked an error)
  std::size_t kept = 0;         ///< rounds[kept] is the mesh kept
  double firstNodes = 0;        ///< the first mesh's nodes when more than one was made
  /// Why the rounds stopped: "error asked", "within tolerance", "count bound by the model",
  /// "metric at hmin / hmax", "rounds", "no mesh" (a round made no mesh: it is returned).
  std::string stop;
  bool reached() const;         ///< the count asked met within kCountTolerance (or an error asked)
};

/// The output's node count of a mesh (order-2 mid nodes included).
std::size_t outputNodes(const MeshResult& r);

/// `from` and `field` as fieldHessians made them; `model` is what `from` is a mesh of.
/// Throws FieldError (AdaptSources.h), and what meshModel throws.
AdaptResult adaptModel(const Model& model, const PatchMesh& from, const FieldHessians& field, const AdaptRequest& request);

}  // namespace aniso
