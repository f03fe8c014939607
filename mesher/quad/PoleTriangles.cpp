#include "mesher/quad/PoleTriangles.h"

namespace aniso::quad {
namespace {

bool onPole(const QuadMesh2d& mesh, const Corners& c) {
  for (int k = 0; k < 3; ++k) {
    const int a = mesh.node[c[k]], b = mesh.node[c[(k + 1) % 3]];
    if (a >= 0 && a == b) return true;
  }
  return false;
}

}  // namespace

void detachTriangle(QuadMesh2d& mesh, int e, std::vector<Corners>& out) {
  for (int k = 0; k < 3; ++k) {
    mesh.boundary[mesh.corners[e][k]] = 1;
    const int f = mesh.adj[e][k];
    if (f == kNone) continue;
    for (int j = 0; j < mesh.sides(f); ++j)
      if (mesh.adj[f][j] == e) mesh.adj[f][j] = kNone;
  }
  out.push_back(mesh.corners[e]);
  mesh.corners[e] = {kNone, kNone, kNone, kNone};
  mesh.adj[e] = {kNone, kNone, kNone, kNone};
}

std::vector<Corners> detachPoleTriangles(QuadMesh2d& mesh) {
  std::vector<Corners> out;
  for (int e = 0; e < mesh.numElements(); ++e)
    if (mesh.isTriangle(e) && onPole(mesh, mesh.corners[e])) detachTriangle(mesh, e, out);
  return out;
}

void reattachTriangles(QuadMesh2d& mesh, const std::vector<Corners>& triangles) {
  for (const Corners& c : triangles) {
    mesh.corners.push_back(c);
    mesh.adj.push_back({kNone, kNone, kNone, kNone});
  }
}

}  // namespace aniso::quad
