#pragma once
// Normals of the faces that meet at a CAD edge, and what they say about the face between
// them.
#include <cstdint>
#include <optional>
#include <vector>

#include "mesher/model/Model.h"

namespace aniso {

/// The normal of face f, oriented as the face (ModelFace::reversed applied: outward for a
/// solid's face), at the middle of edge e; nullopt when e has no pcurve on f or f no
/// surface.
std::optional<Vec3> faceNormalAtEdgeMiddle(const Model& model, const ModelEdge& e, int f);

/// Two faces face opposite ways when their normals' cosine is below minus this.
inline constexpr double kOpposedNormalCos = 0.9;

/// Two edges of a face face each other across it when their middles are closer than this
/// fraction of the shorter one's length (the long sides of a strip).
inline constexpr double kFacingRatio = 0.1;

/// Per face: is it the rim of a film — do the faces it meets across two edges that face
/// each other across it face opposite ways there (the bottom and the top of a sheet as thin
/// as the face is narrow)? The neighbours are oriented as a shell holding the face orients
/// them (a face two solids share faces out of one of them only: a film lying on a part
/// has the part's top face as its bottom). A step of the surface (a riser between two faces
/// facing the same way) is not; nor are the risers at a riser's ends (they face opposite
/// ways, but across its length).
std::vector<std::uint8_t> filmRims(const Model& model);

}  // namespace aniso
