#pragma once
// The point of a CAD edge at a parameter, as the faces that meet there see it.
//
// An edge carries a 3D curve c and, on each face f it bounds, a pcurve p_f whose image
// S_f(p_f(t)) is the same point within the edge's tolerance (OCCT's SameParameter). Some
// exporters and boolean operations leave a 3D curve that strays beyond its tolerance from
// the faces while the faces still agree with each other (an intersection curve
// approximated loosely, straying several times its tolerance; docs/measurements.md). A
// mesh node placed on such a curve lies off both faces, and the face mesher, which works on
// the pcurves, folds triangles over it. The rule:
//   the 3D curve's point c(t), unless the edge has pcurves on at least two faces, their
//   images agree with one another within the tolerance (max(edge tolerance, the faces'))
//   and c(t) is farther than that tolerance from their mean: then the mean.
// A degenerate edge (null curve) returns its pcurves' mean image; NaN when nothing is
// defined at t.
#include "mesher/model/Model.h"

namespace aniso {

/// The node position of edge `edge` (0-based) at parameter t by the rule above.
Vec3 edgePoint(const Model& model, int edge, double t);

}  // namespace aniso
