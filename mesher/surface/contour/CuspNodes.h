#pragma once
// CuspNodes — matched edge nodes at the sharp corners of a face, for quad meshes (thesis
// 4.3 and 4.7). Where two edges of a face meet at a loop corner under kQuadCornerAngle
// (CornerParity.h) — typically a tangential cusp, as where a fillet runs out between two
// faces — the face is a sliver near the corner: its width w is far below the segment
// length h. A quad in a sliver has a scaled Jacobian ≥ 0.1 only when its two sides across
// the sliver join nodes facing each other (stagger along the sliver under about 10 w), so
// with the nodes of the two edges placed independently (each at equal metric spacing) the
// sliver stays a strip of needle triangles that no quad operator can pair.
//
// matchCuspNodes moves the inner nodes of the two edges near each such corner so that the
// k-th node from the corner on one edge and the k-th on the other are at the same 3D
// distance from the corner vertex (the mean of their two distances): the node pairs face
// each other across the sliver (the chord between them is perpendicular to the bisector
// of the corner), and the strip becomes a ladder of quads. Pairs are matched outward from
// the corner while the two nodes are closer to each other than the local segment length
// (the sliver: beyond it the face is wide enough for any quad), their distances differ by
// less than half that length, and k stays in the half of each edge nearer the corner; the
// first pair that fails ends the ladder. Each node moves along its edge within its
// neighbours (bisection on the distance, so the parameters stay increasing); the segment
// counts do not change, so parity (CornerParity.h) and conformity are kept.
#include <vector>

#include "mesher/control/ControlSpace2d.h"
#include "mesher/model/Model.h"

namespace aniso::contour {

/// t[e]: the node parameters of edge e, increasing, both ends included (empty for an edge
/// that is not discretized). Faces with spaces[f] == nullptr are not meshed and skipped.
/// Returns the number of nodes moved.
int matchCuspNodes(const Model& model, const std::vector<const ControlSpace2d*>& spaces,
                   std::vector<std::vector<double>>& t);

}  // namespace aniso::contour
