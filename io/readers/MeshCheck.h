#pragma once
// MeshCheck — what `anisomesh check` finds in a mesh read from a file (ReadMesh.h).
//
//   counts: elements by type, and by type within each group; node sets (INP) by size.
//   surface: the boundary of the tetrahedra when there are any (faces used by one
//     tetrahedron, oriented outward), else the triangles and quads; its edges counted as
//     open (one face), non-manifold (more than two) and misoriented (two faces running the
//     same way); for a volume mesh also tetrahedron faces shared by more than two.
//   validity: degenerate triangles and tetrahedra (zero area or volume up to round-off);
//     inverted tetrahedra (signed volume < 0, or for 10-node ones a Jacobian ≤ 0 at a
//     corner or the centroid), folded 6-node triangles (Jacobian against the corners'
//     normal ≤ 0) and quads (scaled Jacobian ≤ 0, or an 8/9-node one's Jacobian ≤ 0).
//   quality (corner nodes): mean ratio of triangles (in 3D) and tetrahedra, every dihedral
//     angle of the tetrahedra, scaled Jacobian of quads: min, average, histogram.
// The mesh is invalid (problems non-empty) with inverted or degenerate elements; for a
// volume mesh also when its boundary is open, non-manifold or misoriented, or a face is
// shared by more than two tetrahedra; for a surface mesh when two faces sharing an edge
// disagree in orientation. An open or non-manifold surface mesh is reported but valid: a
// surface model may be open, and faces shared by the solids of an assembly meet in threes.
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "io/readers/ReadMesh.h"

namespace aniso::io {

struct QualityHistogram {
  long long count = 0;
  double min = 0, max = 0, sum = 0;
  double lo = 0, hi = 1;          ///< histogram range; values outside go to the end bins
  std::vector<long long> bins;    ///< equal bins over [lo, hi]

  QualityHistogram(double l = 0, double h = 1, int n = 10) : lo(l), hi(h), bins(n, 0) {}
  void add(double v);
  double average() const { return count ? sum / count : 0; }
};

struct MeshCheckReport {
  std::string format;
  long long nodes = 0;
  std::vector<std::pair<std::string, long long>> elements;  ///< by type, in CellType order
  struct Group {
    std::string name;
    std::vector<std::pair<std::string, long long>> elements;
  };
  std::vector<Group> groups;
  std::vector<std::pair<std::string, long long>> nodeSets;

  bool volume = false;  ///< has tetrahedra: the surface checked is their boundary
  long long surfaceFaces = 0, openEdges = 0, nonManifoldEdges = 0, misorientedEdges = 0;
  long long nonManifoldFaces = 0;  ///< volume meshes: faces of more than two tetrahedra
  long long inverted = 0, degenerate = 0;
  long long unchecked = 0;  ///< 3D elements other than tetrahedra (counted only)

  QualityHistogram triangleMeanRatio, tetMeanRatio, quadScaledJacobian;
  QualityHistogram tetDihedral{0, 180, 18};  ///< degrees, six angles per tetrahedron

  std::vector<std::string> problems;  ///< why the mesh is invalid; empty when valid
  bool closed() const { return openEdges == 0; }
  bool manifold() const { return nonManifoldEdges == 0 && nonManifoldFaces == 0; }
  bool oriented() const { return misorientedEdges == 0; }
  bool valid() const { return problems.empty(); }
};

MeshCheckReport checkMesh(const ReadMesh& mesh);

}  // namespace aniso::io
