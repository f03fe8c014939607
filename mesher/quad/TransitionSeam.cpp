#include "mesher/quad/TransitionSeam.h"

#include <algorithm>
#include <array>


namespace aniso::quad {

TransitionResult transitionSeam(QuadMesh2d& mesh, VertexMetrics& metrics, int e, int k, bool left,
                                const SeamOptions& seam, const TransitionSeamOptions& o) {
  TransitionResult r;
  SeamCorner sc;
  if (!seamCorner(mesh, metrics, e, k, left, seam.seamAngle, sc)) return r;
  // The triangle (a, b, c) in its own order: edges a→b (index i) and c→a (index i + 2).
  const int a = sc.a, b = sc.b, c = sc.c, i = sc.i;
  const double lb = metrics.length(a, b), lc = metrics.length(a, c);
  const bool longB = lb >= lc;
  if (!(std::max(lb, lc) > o.seamRatio * std::min(lb, lc))) return r;
  const int L = longB ? b : c, s = longB ? c : b;
  const int q0 = mesh.adj[e][longB ? i : (i + 2) % 3];
  if (q0 == kNone || !mesh.isQuad(q0) || mesh.cornerIndex(q0, s) != kNone) return r;
  const Corners quad = mesh.corners[q0];
  const int j = mesh.cornerIndex(q0, a);
  // Q runs L→a→q (L = b) or q→a→L (L = c), counter-clockwise.
  if (quad[longB ? (j + 3) % 4 : (j + 1) % 4] != L) return r;
  const int q = quad[longB ? (j + 1) % 4 : (j + 3) % 4];
  const double before = elementQuality(mesh, metrics, quad);
  const int m = mesh.addVertex(0.5 * (mesh.uv[a] + mesh.uv[L]));
  metrics.invalidate(m);
  Corners reshaped = quad;
  reshaped[j] = m;
  const Corners n = longB ? Corners{a, q, m, s} : Corners{a, s, m, q};
  const Corners rest{m, b, c, kNone};
  const double qn = elementQuality(mesh, metrics, n), qr = elementQuality(mesh, metrics, reshaped);
  if (!(qn >= seam.minQuality && qr > 0 && qr >= std::min(seam.minQuality, before) && convexCCW(mesh, rest))) {
    mesh.removeLastVertex();
    metrics.invalidate(m);
    return r;
  }
  const std::array<int, 2> removed{e, q0};
  const std::array<Corners, 3> added{reshaped, n, rest};
  const std::vector<int> ids = mesh.replacePatch(removed, added);
  r.done = true;
  r.vertex = m;
  r.reshaped = ids[0];
  r.quad = ids[1];
  r.from = q0;
  return r;
}

}  // namespace aniso::quad
