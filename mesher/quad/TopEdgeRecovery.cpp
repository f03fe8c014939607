#include "mesher/quad/TopEdgeRecovery.h"

#include <array>

#include "mesher/predicates/Predicates.h"
#include "mesher/quad/TriangleFlip.h"

namespace aniso::quad {
namespace {

using predicates::orient2d;

double orient(const QuadMesh2d& mesh, int a, int b, int c) {
  return orient2d(mesh.uv[a].data(), mesh.uv[b].data(), mesh.uv[c].data());
}

struct Crossing {
  int f, k;  ///< triangle f's edge k is crossed
};

/// The triangle edges crossed by c→d, in order from c; empty with `ok` false when the
/// segment leaves the region or touches a vertex.
std::vector<Crossing> crossings(const QuadMesh2d& mesh, int c, int d, int hint, bool& ok) {
  ok = false;
  std::vector<Crossing> out;
  std::vector<int> around;
  bool closed = false;
  mesh.star(c, hint, around, closed);
  int f = kNone, k = kNone;
  for (int g : around) {
    if (!mesh.isTriangle(g)) continue;
    const int i = mesh.cornerIndex(g, c);
    const int x = mesh.corners[g][(i + 1) % 3], y = mesh.corners[g][(i + 2) % 3];
    if (orient(mesh, c, x, d) > 0 && orient(mesh, c, d, y) > 0) {
      f = g;
      k = (i + 1) % 3;
    }
  }
  while (f != kNone && out.size() < 64) {
    out.push_back({f, k});
    const int x = mesh.corners[f][k], y = mesh.corners[f][(k + 1) % 3];
    const int g = mesh.adj[f][k];
    if (g == kNone || !mesh.isTriangle(g)) return {};
    const int j = mesh.edgeIndex(g, y, x);
    const int w = mesh.corners[g][(j + 2) % 3];
    if (w == d) {
      ok = true;
      return out;
    }
    const double s = orient(mesh, c, d, w);
    if (s == 0) return {};
    // x lies right of c→d, y left: the segment leaves g across (x, w) when w is left, else (w, y).
    f = g;
    k = s > 0 ? (j + 1) % 3 : (j + 2) % 3;
  }
  return {};
}

}  // namespace

int elementAt(const QuadMesh2d& mesh, int v, int hint) {
  if (hint != kNone && mesh.alive(hint) && mesh.cornerIndex(hint, v) != kNone) return hint;
  if (hint == kNone || !mesh.alive(hint)) return kNone;
  for (int k = 0; k < mesh.sides(hint); ++k) {
    const int g = mesh.adj[hint][k];
    if (g != kNone && mesh.cornerIndex(g, v) != kNone) return g;
  }
  return kNone;
}

bool hasEdge(const QuadMesh2d& mesh, int c, int d, int hintAtC) {
  std::vector<int> around;
  bool closed = false;
  mesh.star(c, hintAtC, around, closed);
  for (int g : around) {
    const int n = mesh.sides(g), i = mesh.cornerIndex(g, c);
    if (mesh.corners[g][(i + 1) % n] == d || mesh.corners[g][(i + n - 1) % n] == d) return true;
  }
  return false;
}

bool recoverTopEdge(QuadMesh2d& mesh, int c, int d, int hintAtC, int maxSwaps) {
  for (int swaps = 0; swaps <= maxSwaps; ++swaps) {
    if (hasEdge(mesh, c, d, hintAtC)) return true;
    bool ok = false;
    const std::vector<Crossing> list = crossings(mesh, c, d, hintAtC, ok);
    if (!ok) return false;
    bool swapped = false;
    for (const Crossing& x : list) {
      // The triangle at c keeps a live id if it is not the one swapped; else the new one at c.
      const int other = mesh.adj[x.f][x.k];
      const bool touchesHint = x.f == hintAtC || other == hintAtC;
      if (flipTriangleEdge(mesh, x.f, x.k) == kNone) continue;
      if (touchesHint) hintAtC = mesh.numElements() - 2;  // the first new triangle has corner p = c when f was at c
      swapped = true;
      break;
    }
    if (!swapped) return false;
    if (!mesh.alive(hintAtC) || mesh.cornerIndex(hintAtC, c) == kNone) {
      // Find an element at c among the two new ones or their neighbours.
      const int n = mesh.numElements();
      hintAtC = kNone;
      for (int e : {n - 2, n - 1}) {
        if (hintAtC != kNone) break;
        hintAtC = elementAt(mesh, c, e);
      }
      if (hintAtC == kNone) return false;
    }
  }
  return false;
}

}  // namespace aniso::quad

