#pragma once
// Thin parts of a solid found after the triangulation of its boundary nodes (thesis
// 3.5.2, alg. 3.3: "update ACS_v with proximity of boundary faces"): where the solid is
// thinner than its surface mesh is coarse, every tet reaches from one side to the other
// and no interior point fits in between (periodic_u_cst: 87 % of the tets had their four
// nodes on the surface). After boundary recovery — carved or not, complete or not: a
// triangle the recovery left missing is skipped — the tet on the inner side of each
// boundary triangle T has an apex x; T is thin when x is a surface node on the opposite side —
// the outward normals at T and at x point against each other (cosine below
// kOppositeNormalCos), x lies on T's inner side — and the height of x over T's plane is
// below kThinRatio times T's mean edge length (a regular tet's apex stands at 0.816 of its
// edge). Folds and corners of the surface (the apex on a neighbouring patch) have normals
// that do not oppose, so they are not reported. Nor are cusps (with the model): the apex's
// CAD face across from T (of the faces around it, the one whose normal there opposes T's
// the most) meets T's face along an edge at an angle below kCuspAngle (their normals at
// the edge's middle opposed). A cusp is thinner than any triangle near its edge, and finer
// triangles make it worse: the tets at the edge have the angle between the chords of the
// two faces, which shrinks with their length (two battery cradles, cylinders tangent along
// the edge imprinted by cad/PrepareSelfContacts).
//
// thinSources() turns the spots into sizing sources for the surface control spaces: per
// CAD face, a box around its thin triangles (grown by the largest of them) that sizes the
// faces of its thin solid only (SizingSource::faces: the other parts in the box, components
// on a thin board, keep their sizes), with the isotropic size of the face's thickness (a
// low quantile of its spots', kFaceThicknessQuantile; not below hmin), so the surface mesher makes
// triangles about as large as the part is thick; spots whose triangles hmin would not make
// smaller (the size at most kThinRatio below them) are left. A source stays clear of the
// model's tangent cusp edges — two of its faces tangent along the edge (kTangentCuspAngle) with
// material between them, the second face parting to the inner side of the first — : its box
// less the box of each such edge grown by kCuspClearance times its size (up to six boxes per
// edge), so that the edge keeps the size of its faces. The tets at such an edge have the angle
// between the chords of its two faces, which finer triangles make flatter
// (docs/measurements.md). `faces` has one entry per box (a face may have several, consecutive).
#include <vector>

#include "mesher/model/Model.h"
#include "mesher/sizing/UserSizing.h"
#include "mesher/surface/SurfaceMesh.h"
#include "mesher/volume/BoundaryTriangulation.h"
#include "mesher/volume/SolidTetMesh.h"

namespace aniso {

/// A thin apex stands lower than this times the boundary triangle's mean edge length.
inline constexpr double kThinRatio = 0.8;
/// The outward normals at the triangle and at the apex oppose below this cosine.
inline constexpr double kOppositeNormalCos = -0.5;
/// Two faces meeting along an edge at less than this angle (radians, 3°) close a cusp.
inline constexpr double kCuspAngle = 0.0523598775598;
/// The thin sources keep clear of the cusp edges whose faces are tangent (normals opposed
/// within this angle, radians: 0.1°) with material between them: there the cusp opens with
/// the distance from the edge and finer triangles make flatter tets. Faces of two parts
/// meeting along an interface edge also have opposed normals but part by nothing; taken as
/// cusps they cost quality for no gain (docs/measurements.md).
inline constexpr double kTangentCuspAngle = 0.00174532925199;
/// A thin source's box keeps this many times its size away from a cusp edge's box: the face
/// control spaces interpolate between their vertices, so a narrower clearance still sized the
/// edge (docs/measurements.md).
inline constexpr double kCuspClearance = 10.0;
/// A solid is too coarse for its thickness when at least this fraction of its boundary
/// triangles is thin: a few thin spots (a narrow rib of a large part) are left to sliver
/// removal, meshing the surface again is for parts that are thin as a whole
/// (docs/measurements.md).
inline constexpr double kThinFraction = 0.05;

/// A face's thin source asks for this quantile of its spots' thicknesses, not the smallest:
/// a thickness is an apex's height over a boundary triangle's plane, which on a coarse
/// curved sheet dips towards the other side (docs/volume.md, "How a solid is meshed"). Spots
/// much thinner than the rest are measured again on the finer surface of the next round.
inline constexpr double kFaceThicknessQuantile = 0.1;

struct ThinSpot {
  int face = -1;       ///< 0-based model face of the boundary triangle
  Vec3 centroid;       ///< of the triangle
  double size = 0;     ///< its mean edge length
  double thickness = 0;  ///< height of the apex across the solid
  int solid = -1;        ///< 0-based model solid it was found in (set by the volume mesher)
};

/// The thin boundary triangles of s; empty when fewer than kThinFraction of them are thin.
/// `b`: the solid's boundary in s's kernel ids (triangulateBoundary: outward, the inner side
/// is where their normal points away from; the embedded triangles are not looked at).
/// With `model`, cusps are left out (see above).
std::vector<ThinSpot> findThinBoundary(const SolidTetMesh& s, const SolidBoundary& b, const Model* model = nullptr);

/// The box sources of the faces with thin spots (see above), faces in increasing order. With
/// `faces`, it receives the (0-based face, size asked) of each source, in the same order.
/// With `model`, each source sizes only the faces of the solids its spots were found in
/// (SizingSource::faces, embedded faces included); without, every face in its box.
std::vector<SizingSource> thinSources(const std::vector<ThinSpot>& spots, double hmin,
                                      std::vector<std::pair<int, double>>* faces = nullptr,
                                      const Model* model = nullptr);

/// Triangles the surface mesh would have with the sources: each triangle whose centroid
/// lies in a source (of its face, for a face's source) counts (mean edge / the smallest size of those sources)² when that is
/// above 1, every other one 1 (for the caller's budget).
double predictedTriangles(const SurfaceMesh& surface, const std::vector<SizingSource>& sources);

/// The sources with their sizes multiplied by the smallest factor s ≥ 1 (to 1 %) for which
/// predictedTriangles stays within `budget`: a part too thin for the budget is refined as
/// far as the budget allows rather than not at all (the tets across a wall get flatter with
/// the ratio of triangle size to thickness, so halfway is much better than nothing).
/// `factor` receives s. The sources themselves when they fit already (s = 1); scaled by
/// `maxFactor` when even that does not fit (the caller checks the prediction).
std::vector<SizingSource> sourcesWithinBudget(const SurfaceMesh& surface, const std::vector<SizingSource>& sources,
                                              double budget, double* factor = nullptr, double maxFactor = 1e6);

/// Indices (ascending) of the sources kept when only part of them fits `budget`: sources
/// are grouped by the faces they size (one group per thin solid, thinSources with a model),
/// each group's growth (predictedTriangles with it alone, less the surface's triangles) is
/// summed in increasing order while the surface plus the sum stays within `budget`; ties
/// keep the source order. For a model thin in places: the thin solids that fit are refined
/// fully, the others keep their surface (rather than none refined, or all scaled coarser).
/// `groups` receives the number of groups, `kept` those taken.
std::vector<std::size_t> cheapestGroupsWithinBudget(const SurfaceMesh& surface,
                                                    const std::vector<SizingSource>& sources, double budget,
                                                    std::size_t* groups = nullptr, std::size_t* kept = nullptr);

}  // namespace aniso
