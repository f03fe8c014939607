#pragma once
// Model — the boundary representation the mesher consumes (thesis sec. 6.2), independent of
// OCCT. cad/ builds it from a CAD file; tests build it from analytic geometry.
//
// Numbering: every entity vector is indexed 0..n−1 and the entity's public id is index+1,
// in OCCT's TopExp::MapShapes order when built from CAD (the numbering FreeCAD's FaceN
// and Gmsh's OCC kernel use). All cross references below are 0-based indices.
#include <string>
#include <vector>

#include "mesher/core/Problem.h"
#include "mesher/core/Types.h"
#include "mesher/geometry/ParametricCurve2d.h"
#include "mesher/geometry/ParametricCurve3d.h"
#include "mesher/geometry/ParametricSurface.h"

namespace aniso {

struct ModelVertex {
  Vec3 p;
  double tolerance = 0;  ///< CAD tolerance of the vertex (model units)
};

/// The parametric curve of an edge on one of its faces. A seam edge (closed periodic
/// surface) has two pcurves on the same face: `seamSecond` marks the one that goes with
/// the edge's REVERSED use in that face.
struct PCurve {
  int face = -1;
  Curve2dPtr curve;
  double t0 = 0, t1 = 0;  ///< parameter range on this pcurve (same as the edge's, OCCT SameParameter)
  bool seamSecond = false;  ///< the pcurve OCCT gives the REVERSED edge in the FORWARD face
};

struct ModelEdge {
  int v0 = -1, v1 = -1;        ///< vertices at t0 and t1 (equal for a closed edge)
  Curve3dPtr curve;            ///< null for a degenerate edge (a pole)
  double t0 = 0, t1 = 0;       ///< parameter range used by the edge
  bool degenerate = false;     ///< collapses to a point in 3D (pole of a sphere, apex of a cone)
  bool seam = false;           ///< is a seam on at least one face (two pcurves there)
  double tolerance = 0;
  std::vector<PCurve> pcurves; ///< one per adjacent face, two on a face where it is a seam
  std::vector<int> faces;      ///< adjacent faces (each once)
};

/// One oriented use of an edge in a loop. Walking the loop, the use runs from the edge's
/// v0 to v1 when !reversed, from v1 to v0 when reversed. Loops follow the face as
/// oriented: for a face that is not reversed the face lies on the left of every use in the
/// (u,v) plane (outer loop counter-clockwise, holes clockwise); for a reversed face it lies
/// on the right. In both cases the face is on the left seen from its oriented normal in 3D.
/// On a seam, `pcurve` points at the pcurve of this use (see PCurve::seamSecond).
/// Edges INTERNAL to a face are slit loops (Loop::slit); EXTERNAL ones have pcurves but
/// appear in no loop.
struct EdgeUse {
  int edge = -1;
  bool reversed = false;
  int pcurve = -1;  ///< index into edges[edge].pcurves
};

struct Loop {
  std::vector<EdgeUse> uses;  ///< in walking order
  bool outer = false;
  /// An edge embedded in the face (OCCT: INTERNAL): one use forward and one back, the face
  /// on both sides; its mesh edges are constraints of the face's triangles, each used by
  /// two of them. After the outer loop and the holes.
  bool slit = false;
};

struct ModelFace {
  SurfacePtr surface;
  bool reversed = false;    ///< the face normal is −(pu × pv)
  std::vector<Loop> loops;  ///< the outer loop first, then the inner loops (holes)
  Box2 uvBounds;            ///< parametric bounds of the face (trimmed)
  double tolerance = 0;
  double cadArea = 0;       ///< the CAD kernel's area of the face; 0 when not known
  std::string name;         ///< the face's own name in the CAD file (STEP), "" when none
};

struct FaceUse {
  int face = -1;
  bool reversed = false;  ///< the face's orientation in this shell (same meaning as ModelFace::reversed)
};

struct ModelShell {
  std::vector<FaceUse> faces;
  bool closed = false;  ///< every edge (not degenerate, not seam) used by exactly two faces
};

/// A face inside a solid's material: both of its sides are the solid (a crack, an internal
/// interface, a baffle; Gmsh's "embedded" surface). Its surface mesh is a constraint of the
/// solid's tetrahedra (conformal). A crack is two-sided: after volume meshing its nodes are
/// duplicated so that the two sides separate (mesher/volume/CrackSplit.h); otherwise the
/// tetrahedra on both sides share its nodes (a bonded interface).
struct EmbeddedFace {
  int face = -1;
  bool crack = false;
};

struct ModelSolid {
  std::string name;            ///< STEP part name, or "SOLID<n>"
  int outerShell = -1;
  std::vector<int> voidShells; ///< inner shells bounding cavities
  std::vector<EmbeddedFace> embedded;  ///< faces inside the material, each once
  double cadVolume = 0;        ///< the CAD kernel's volume of the solid (adaptive integral); 0 when not known
};

/// One finding of Model::check(), on the entity (kind, 0-based index) it concerns.
struct ModelIssue {
  enum class Level {
    Defect,    ///< inconsistent but usable within the CAD tolerance (a loop closing only
               ///< within tolerance or in 3D, a shell flagged closed with a non-manifold edge)
    Gap,       ///< usable, but a loop is open beyond the CAD tolerance: meshed across the gap
    Unusable,  ///< the entity cannot be meshed (missing geometry or references)
  };
  EntityKind kind = EntityKind::Model;
  int index = -1;
  Level level = Level::Unusable;
  std::string message;  ///< names the entity by its 1-based id
  /// For a loop that does not close: its (u, v) gap, whole periods of a periodic surface
  /// removed, over the face's parametric extent (the larger of the two axes); 0 otherwise.
  /// The face mesher closes a narrow gap at its midpoint and bridges a wide one whose
  /// straight (u, v) segment stays at the vertex in 3D as a pole (surface/contour/FaceLoops.cpp).
  double uvGapShare = 0;
};

struct Model {
  std::vector<ModelVertex> vertices;
  std::vector<ModelEdge> edges;
  std::vector<ModelFace> faces;
  std::vector<ModelShell> shells;
  std::vector<ModelSolid> solids;
  Box3 bbox;

  /// Size of the model: the bounding-box diagonal. Tolerances and sizes relative to the
  /// model (--hmax-rel, the g_min guard, ...) are taken relative to this.
  double diagonal() const { return bbox.diagonal(); }

  /// Structural checks: references in range, every loop closed in parametric space within
  /// tolerance (jumps by whole periods of a periodic surface allowed), pcurves present for
  /// every (edge, face) use. One issue per problem, graded by what the mesher can still do
  /// with the entity; empty when valid.
  std::vector<ModelIssue> check() const;
  /// The faces (0-based) of solid s's shells: its void shells', then its outer shell's, each
  /// in shell order (a face used twice appears twice); shell references out of range skipped.
  std::vector<int> solidFaces(int s) const;
  /// Every face bounding or inside solid s: solidFaces(s) and its embedded faces,
  /// ascending, each once.
  std::vector<int> solidBoundaryFaces(int s) const;
  /// check()'s messages, each naming the entity by its 1-based id.
  std::vector<std::string> validate() const;
};

}  // namespace aniso
