#pragma once
// VertexNearEdge — edge nodes where a loop corner of a face comes close to another edge of
// the same face (a hole's corner near the outer boundary, a pad near a rim). A segment of
// a curved edge is its chord in (u, v); the chord cuts off the lens between itself and the
// arc, up to the segment's sagitta s (the arc's largest distance from the chord). A corner
// closer to the arc than the chord error can lie in that lens, or beyond the chord: the
// discretized loops then cross in (u, v) and the face cannot be meshed, although the CAD
// loops do not touch (docs/measurements.md).
//
// addNodesNearVertices puts a node on the edge at the point nearest to such a corner: the
// discretized edge then passes through the point of the arc next to the corner, and the
// chords on either side leave it at the arc's own distance. A corner counts for a segment
// when it lies in the segment's box grown by kNearVertexSagitta × s and the arc passes
// within kNearVertexSagitta × s of it; the node is added when it falls strictly inside
// the segment (kNearVertexMargin of its parameter length from either end). Corners of the
// edge itself are not considered. On a periodic surface the corner is taken one whole
// period at a time nearest to the segment. At most kNearVertexRounds passes (a new node
// can bring another corner into a smaller lens). Deterministic; faces whose control space
// is null are skipped.
#include <vector>

#include "mesher/control/ControlSpace2d.h"
#include "mesher/model/Model.h"

namespace aniso::contour {

inline constexpr double kNearVertexSagitta = 2.0;
inline constexpr double kNearVertexMargin = 0.02;
inline constexpr int kNearVertexRounds = 3;

/// t[e]: the node parameters of edge e, increasing, both ends included (empty for an edge
/// not discretized); nodes are added in place. Returns the number of nodes added.
int addNodesNearVertices(const Model& model, const std::vector<const ControlSpace2d*>& spaces,
                         std::vector<std::vector<double>>& t);

}  // namespace aniso::contour
