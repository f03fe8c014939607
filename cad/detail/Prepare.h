#pragma once
// Internal: the preparation steps run by CadModel::prepare(), each its own operator.
// Every step keeps the part names of solids: it rebinds impl.nameIndex for the images; and
// the STEP face names and colours: it passes impl.faceTagIndex on by its history (FaceTags.h).
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <BRepTools_History.hxx>
#include <ShapeBuild_ReShape.hxx>
#include <TopoDS_Compound.hxx>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "cad/detail/CadModelImpl.h"

namespace aniso::cad::detail {

/// ShapeFix_Shape on the whole shape (wires, edges, faces, shells, solids), the internal
/// faces it dropped put back (restoreInternalFaces), then rebuildSelfIntersecting.
void fixShape(CadModel::Impl& impl, double diag, PrepareReport& report);

/// Records in `context` (ShapeFix_Shape's, before it runs) a replacement for every face with
/// a loop made of two or more edges each closed on itself, none joined to the next (two rim
/// circles of a cylinder in one loop, no seam): the loop becomes one loop per edge, and
/// ShapeFix_Face then adds the missing seam. Returns the faces changed.
int splitLoopsOfClosedEdges(const TopoDS_Shape& shape, ShapeBuild_ReShape& context);

/// Solids whose faces cross or touch one another (BOPAlgo_ArgumentAnalyzer's
/// self-interference: BRepCheck calls them valid, the volume mesher finds their boundary
/// crossing itself) rebuilt from their faces by BOPAlgo_MakerVolume, faces split where they
/// meet; a solid is replaced only when the rebuilt pieces, each counted as often as the
/// solid's faces wind around it, add up to its volume (a solid overlapping itself counts the
/// overlap twice: kept once, its volume in PrepareReport::selfOverlapVolume). Pieces that
/// touch themselves along an edge are replaced by their union; a solid that only touched
/// itself comes back as one piece of the same volume, the edge it touched itself along now
/// shared by the face it lay on. Run at the end of fixShape. A warning names the solids
/// rebuilt.
void rebuildSelfIntersecting(CadModel::Impl& impl, PrepareReport& report);

/// Solids two of whose faces touch along a line through both, without an edge there (two
/// battery cradles, cylinders tangent to one another, pinch the wall between them to
/// nothing): the line is imprinted on both faces (general fuse of the solid and the line's
/// edge), which become four faces sharing that edge, so that the mesh has nodes on it
/// rather than two surfaces a tolerance apart, a cusp no tetrahedron fits. Found between
/// cylinders with parallel axes as far apart as their radii add up or differ, and between
/// a cylinder and a plane along its axis at its radius (analytic faces only); kept when
/// the solid stays valid, of the same volume to 1e-5, each edge between four faces. Run
/// after rebuildSelfIntersecting. A warning names the solids.
void imprintSelfContacts(CadModel::Impl& impl, PrepareReport& report);

/// A fin a contact edge bounds, taken off its solid (imprintSelfContacts): above the line
/// where two battery cradles touch stands a fin far thinner than it is tall, whose
/// tetrahedra cannot have angles above a few degrees (docs/measurements.md). The fin is the
/// faces on one side of the edge (two of them closing a cusp there, at under 3°),
/// flooded up to the holes of other faces they end on (its cross-section where it runs into
/// a wall); without them, and without those holes, the solid stays closed and valid. Taken
/// off when it holds at most 1e-3 of the solid's volume and is on average (2 V / A) at most
/// 1e-3 of the model's diagonal thick. Every such fin is taken off (`volume` their sum,
/// `thickness` the thickest).
struct FinRemoval {
  TopoDS_Shape solid;
  double volume = 0;     ///< taken off
  double thickness = 0;  ///< the fin's mean thickness, 2 V / A
  Handle(BRepTools_History) history;
};
std::optional<FinRemoval> withoutCuspFins(const TopoDS_Shape& solid, const std::vector<TopoDS_Shape>& contactEdges,
                                          double diag);

/// The INTERNAL faces of each solid of a shape (faces inside its material: a crack, an
/// interface; ModelSolid::embedded) and the faces of its sheet shells (SheetShell.h), solid
/// by solid, with their placement in the shape.
struct InternalFacesOf {
  TopoDS_Shape solid;
  int index = 0, count = 0;  ///< the solid's 1-based place among the shape's `count` solids
  TopTools_ListOfShape faces;
};
using InternalFaces = std::vector<InternalFacesOf>;
InternalFaces collectInternalFaces(const TopoDS_Shape& shape);

/// ShapeFix drops a solid's shell made only of INTERNAL faces: puts back, into every solid
/// `kept` lists whose image (through the fixer's context, else at the same place among the
/// solids when their number is kept) has none of those faces left, a
/// shell of those faces (their sub-shapes renamed through the context, so the edges they
/// share with the solid's faces stay shared). The shape then becomes a compound of its
/// solids and loose faces; part names follow. Returns the solids changed.
int restoreInternalFaces(CadModel::Impl& impl, const InternalFaces& kept, const Handle(ShapeBuild_ReShape)& context);

/// Sews the faces that are not in a solid (loose faces, open shells) with tolerance
/// tol; keeps the result only if it leaves fewer free edges. Solids are not touched.
void sewLooseFaces(CadModel::Impl& impl, double tol, PrepareReport& report);

/// A face whose CAD area is at most this fraction of the squared diagonal has none: the
/// fuse leaves such faces where it splits a face along a line it already bounds.
inline constexpr double kNoAreaRel = 1e-12;

/// A loop closed in 3D within the CAD tolerance whose (u, v) gap exceeds this share of the
/// face's parametric extent is meshed only by bridging the gap as a pole (FaceLoops.cpp): a
/// fuse that leaves such loops where there were none is not trusted. (Trusting it emptied a
/// solid of a real part: docs/measurements.md.)
inline constexpr double kFuseLoopGapShare = 0.1;

/// For each part (a set of solids of `whole`), how many of its faces the mesher's own rule
/// finds wanting in `whole`: an issue of Model::check that is not a Defect (a loop open
/// beyond the tolerance, an unusable face), a Defect whose (u, v) gap exceeds
/// kFuseLoopGapShare, or no area (kNoAreaRel). When the mesher cannot read `whole` at all,
/// every part counts all its faces.
std::vector<int> flawedFaceCounts(const TopoDS_Shape& whole, const std::vector<TopTools_IndexedMapOfShape>& parts);

/// General fuse of the solids so that touching solids share their interface faces. Parts
/// that touch within the model's tolerance are glued: the fuzzy value is the largest
/// vertex/edge tolerance, between 1e-7 and 1e-6 of the diagonal, and the fuse falls back to
/// 1e-7 × diagonal if that one fails. Overlapping solids are reported (report.overlaps, ids
/// as in the current shape) and then, by `policy`: Merge — every common region is kept in
/// one part (OverlapRule.h) and the others lose it; Keep — the whole shape is left
/// unfragmented; Error — InputError naming the first pair. A failed fuse, or one whose
/// images do not add up to their solids' volumes, leaves the shape as it was, with a warning.
void fragmentSolids(CadModel::Impl& impl, double diag, OverlapPolicy policy, PrepareReport& report);

/// The solids a part made of several fuse pieces becomes: the faces shared by two pieces
/// are dropped and the rest rebuilt into solids (BOPAlgo_BuilderSolid) from the same faces,
/// so the interfaces with other parts stay shared. The pieces themselves if that fails or
/// gives a volume that matches neither the pieces' sum nor `partVolume`, the part's volume
/// before the fuse (a fuzzy fuse loses slivers of its pieces' volume along the interfaces
/// it glues, while the merged solid keeps the part's volume: docs/measurements.md).
TopTools_ListOfShape mergePieces(const TopTools_ListOfShape& pieces, double partVolume);

/// For a region common to several parts (a solid of the general fuse) and the parts' solids
/// before the fuse: per part, the narrowest face of the region that lies on that part's
/// boundary (within `tol`), as 2 × area / perimeter; infinity when none does. Keeping the
/// region in part i adds exactly those faces to the other parts' boundaries.
std::vector<double> regionFaceWidths(const TopoDS_Shape& region, const std::vector<TopoDS_Shape>& parts, double tol);

/// A number for messages: 6 significant digits (%.6g).
std::string num(double v);

/// Volume of a solid (OCCT GProp), 0 if OCCT fails.
double solidVolume(const TopoDS_Shape& solid);
/// Area of a shape's faces (OCCT GProp), 0 if OCCT fails.
double shapeArea(const TopoDS_Shape& shape);

/// Adds to `c` the faces of `shape` that are in none of `solids` (loose faces, open shells):
/// what a step that rebuilds the solids into a new compound keeps besides them.
void addLooseFaces(const TopoDS_Shape& shape, const TopTools_IndexedMapOfShape& solids, TopoDS_Compound& c);

/// impl.shape rebuilt with solid i (1-based, of `solids`) replaced by the pieces
/// replacement[i] when there are any: the solids in order, then the loose faces (as the
/// fragmenting step assembles its result); the pieces take the solid's part name, and the
/// STEP face tags pass on through history[i].
void replaceSolids(CadModel::Impl& impl, const TopTools_IndexedMapOfShape& solids,
                   const std::vector<std::vector<TopoDS_Shape>>& replacement,
                   const std::vector<Handle(BRepTools_History)>& history);

/// Number of edges (not degenerate) bounding exactly one face of the shape.
int countFreeEdges(const TopoDS_Shape& shape);

}  // namespace aniso::cad::detail

namespace aniso::cad::detail {

/// Runs one preparation step (fixShape, sewLooseFaces, fragmentSolids) in a child process
/// (ChildProcess.h), so that a crash of OCCT there costs the step, not the run: the shape
/// and the report are then kept as they were before the step, with a warning naming it.
/// `crashPoint` is the step's test hook (testCrashPoint), e.g. "prepare-fix".
void runPrepareStep(const char* step, const char* crashPoint, CadModel::Impl& impl, PrepareReport& report,
                    const std::function<void(CadModel::Impl&, PrepareReport&)>& run);

}  // namespace aniso::cad::detail
