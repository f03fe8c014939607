#pragma once
// BackgroundMeshKernel<D> — the Delaunay kernel under BackgroundMesh<D> (thesis sec. 3.4:
// the control mesh is "stored and managed in a way similar to the actual mesh being
// generated, using the same set of meshing procedures"), one specialisation per dimension:
// BackgroundMeshKernel2d.h (triangles of del2d::Triangulation2d) and
// BackgroundMeshKernel3d.h (tetrahedra of del3d::TetMesh). BackgroundMesh<D> holds the
// per-vertex metrics and every procedure that is the same in both dimensions; a kernel
// holds only what differs: the element type, point location, insertion, stars, the
// element geometry (centroid, closure test, circumcentre, in-sphere test, edge lengths)
// and validation.
//
// Interface of a specialisation (all element ids are of type Elem, all vertex ids plain
// indices; a const method never modifies the kernel, so concurrent queries are safe once
// settle() has run after the last modification):
//   kCorners, kEdges[k] (local vertex pairs: the check edges of BackgroundCheck::
//   CentroidEdges, in the order they are checked), kElementName;
//   numVertices, point, coords, slots, isAlive, vertices, neighbour, vertexElement;
//   locate(p, start, rng)   the live element whose closure contains p (ties broken
//                           towards the smallest slot), or an invalid id when it fails;
//   insert(p, near)         Bowyer–Watson insertion in the identity metric: the new or
//                           coinciding vertex (−1 when refused);
//   appendCreated(v, out)   the elements the last insert(…) created for vertex v;
//   appendStar(v, out)      every live element incident to v;
//   edgePairs()             the vertex pairs of the edges of the live elements;
//   centroid, closureContains, circumcentre (not finite for a flat element), inSphere
//                           (strictly inside the circumsphere), maxEdgeLength(t, M);
//   validate()              the kernel's invariants with the Delaunay property (identity);
//   settle()                ends a modification (brings lazily built search structures up
//                           to date, so that queries only read them).
#include <cstdint>

namespace aniso {

template <int D>
class BackgroundMeshKernel;

/// What a kernel insertion did: the new or coinciding vertex (−1 when refused) and
/// whether it was created.
struct KernelInsertion {
  int vertex = -1;
  bool created = false;
};

}  // namespace aniso
