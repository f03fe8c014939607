#pragma once
// CornerParity — segment-count parity for quad meshes at sharp corners (thesis 4.3, made
// exact). A face meshed in quads with T triangles left and B boundary segments satisfies
// T ≡ B (mod 2) (4Q + 3T = 2·inner edges + B). A loop corner with an interior angle below
// kQuadCornerAngle (asin 0.1: any quad there has a scaled Jacobian under 0.1) keeps a
// triangle, so a face with k such corners should have B ≡ k (mod 2), not B even: with
// every count even, an odd k leaves one more triangle than the corners force.
//
// Given even counts n (one per model edge), makeCornerParity raises by one the counts of
// a set of edges chosen so that every meshed face f gets B_f ≡ k_f (mod 2): a T-join in the
// graph whose nodes are the meshed faces plus one "free" node and whose links are the
// edges (an edge used by two faces links them, an edge used by one face links it to the
// free node; seam uses by one face cancel; degenerate and non-manifold edges are no
// links). Spanning trees are grown from the free node first, then from the lowest face
// index, links taken longest first (most segments, then lowest index): deterministic. A
// component without the free node and an odd number of odd faces keeps one face off by
// one (one extra triangle there). Corner angles are measured in 3D between short chords
// of the two edge uses, in the tangent plane at the vertex, on the face's side (the face
// lies on the left of its loops seen from its oriented normal; see Model.h).
#include <vector>

#include "mesher/control/ControlSpace2d.h"
#include "mesher/model/Model.h"

namespace aniso::contour {

/// Interior angle (radians) below which a quad corner cannot reach scaled Jacobian 0.1.
inline constexpr double kQuadCornerAngle = 0.100167421161559796;  // asin(0.1)

/// A loop corner of a face: loops[loop].uses[in] arrives at the vertex, uses[out] leaves it.
struct LoopCorner {
  int loop, in, out;
};

/// The loop corners of face f with an interior angle below kQuadCornerAngle, in loop order.
std::vector<LoopCorner> sharpCornerList(const Model& model, int f);

/// The number of loop corners of face f with an interior angle below kQuadCornerAngle.
inline int sharpCorners(const Model& model, int f) { return static_cast<int>(sharpCornerList(model, f).size()); }

/// Raises n[e] by one on the T-join's edges (see above); faces with spaces[f] == nullptr
/// are not meshed and ignored. Returns how many counts were raised.
int makeCornerParity(const Model& model, const std::vector<const ControlSpace2d*>& spaces,
                     const std::vector<char>& used, std::vector<int>& n);

}  // namespace aniso::contour
