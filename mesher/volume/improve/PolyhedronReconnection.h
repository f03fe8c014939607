#pragma once
// Small polyhedron reconnection (after Liu et al.'s SPR; issue 5 §1, slivers no flip,
// edge removal or vertex move removes): the sliver t and the tets around it — those across
// its unconstrained faces, then every tet across an unconstrained face of those whose four
// vertices are all among theirs, at most kMaxReconnectionTets — are replaced by another
// tetrahedralization of their union P with the same vertices and the same boundary
// faces, the one whose smallest dihedral angle is largest (Euclidean, the referee's
// measure of a sliver; branch and bound), when it beats the smallest of the tets it
// replaces. (The mean ratio would not do: a tiling of better worst mean ratio can hold a
// flatter dihedral angle.) When there is none, the polyhedron grown by the
// tet across one of its unconstrained faces (and closed again) is tried, face by face, then
// those grown once more (breadth first, each polyhedron once, kMaxReconnectionTries in all).
//
// The case it is for: a film whose top and bottom were meshed alike, each top node just
// above a bottom one (a label a micrometre thick). Its tets fill prisms between such columns,
// and where two neighbouring prisms split the wall between two columns by different
// diagonals a flat tet on the wall's four nodes fills the gap; every flip of it or edge
// removal around it makes another such tet. Re-splitting the two prisms together, the
// wall by one diagonal, removes it — or, when their other walls leave one of them no
// split with that diagonal, together with a third prism.
//
// The search fills P face by face from its boundary (a front of open faces, each with its
// inner side): a candidate tet on the first open face has a vertex of P on the inner side
// (exact orient3d), no face of it lies open on its own side or already closed, and a
// smallest dihedral angle above the best found; its faces close open faces or open new ones. A front that
// empties is a tetrahedralization of P: its tets are positively oriented and its boundary
// is P's, so they cover P once. It must use every vertex of P (none disappears). At most
// kMaxReconnectionSteps candidate tets are tried per polyhedron, kMaxReconnectionTotalSteps
// in one call. Check, then change (del3d::replaceTets):
// the hull and the constrained faces are unchanged (validateSolidTetMesh holds);
// deterministic (fixed orders).
#include <cstddef>
#include <vector>

#include "mesher/volume/SolidTetMesh.h"

namespace aniso::improve3d {

/// At most this many tets in the polyhedron (and in its new tetrahedralization).
inline constexpr std::size_t kMaxReconnectionTets = 12;
/// At most this many vertices in the polyhedron.
inline constexpr std::size_t kMaxReconnectionVertices = 10;
/// Bounds of the search: candidate tets tried for one polyhedron, and over all the
/// polyhedra of one call (a call stays within tens of milliseconds, and a label's film needs
/// only a few calls: docs/measurements.md).
inline constexpr int kMaxReconnectionSteps = 5000;
inline constexpr int kMaxReconnectionTotalSteps = 200000;
/// When the polyhedron has no better tetrahedralization, it grown by the tet across one of
/// its faces (then closed as above), then by one more, is tried: at most this many growths
/// in a row and this many polyhedra in all.
inline constexpr std::size_t kMaxReconnectionGrowths = 2;
inline constexpr std::size_t kMaxReconnectionTries = 40;

/// Replaces the live tet t and the tets around it (above) by their best tetrahedralization
/// when its smallest dihedral angle beats theirs; appends the new tets to `created` and
/// returns true (t is then dead).
bool reconnectPolyhedron(SolidTetMesh& s, del3d::TetId t, std::vector<del3d::TetId>& created);

}  // namespace aniso::improve3d
