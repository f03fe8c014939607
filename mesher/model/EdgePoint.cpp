#include "mesher/model/EdgePoint.h"

#include <algorithm>
#include <limits>

namespace aniso {

Vec3 edgePoint(const Model& model, int edge, double t) {
  const ModelEdge& ed = model.edges[static_cast<std::size_t>(edge)];
  const Vec3 nan = Vec3::Constant(std::numeric_limits<double>::quiet_NaN());
  const Vec3 c = ed.curve ? ed.curve->point(t) : nan;
  // The images of the pcurves on distinct faces (a seam's second pcurve is the same face).
  Vec3 sum = Vec3::Zero();
  Vec3 images[8];
  int face[8];
  int n = 0, faces = 0;
  double tolerance = ed.tolerance;
  for (const PCurve& pc : ed.pcurves) {
    if (!pc.curve || n == 8 || pc.face < 0 || static_cast<std::size_t>(pc.face) >= model.faces.size()) continue;
    const ModelFace& f = model.faces[static_cast<std::size_t>(pc.face)];
    if (!f.surface || t < std::min(pc.t0, pc.t1) || t > std::max(pc.t0, pc.t1)) continue;
    const Vec3 p = f.surface->point(pc.curve->point(t));
    if (!p.allFinite()) continue;
    face[n] = pc.face;
    if (std::find(face, face + n, pc.face) == face + n) ++faces;
    images[n++] = p;
    sum += p;
    tolerance = std::max(tolerance, f.tolerance);
  }
  if (n == 0) return c;
  const Vec3 mean = sum / n;
  if (!c.allFinite()) return mean;
  if (faces < 2) return c;
  for (int i = 0; i < n; ++i)
    if ((images[i] - mean).norm() > tolerance) return c;  // the faces disagree: keep the curve
  return (c - mean).norm() > tolerance ? mean : c;
}

}  // namespace aniso
