#pragma once
// Node orders of the output formats, as positions in our canonical order (corners, then
// mid-edge nodes: triangle (0,1) (1,2) (2,0); quad (0,1) (1,2) (2,3) (3,0); tetrahedron
// VolumeMesh::kTetEdges = (0,1) (1,2) (2,0) (0,3) (1,3) (2,3)): written node k of a
// format is canonical node order[k].
//   Gmsh (MSH types 2 9 3 16 4 11): canonical, except tet10 whose nodes 8 and 9 are on
//     the edges (3,2) and (3,1) (Gmsh manual, "Node ordering").
//   Abaqus/CalculiX (S3 S6 S4 S8 C3D4 C3D10) and VTK (5 22 9 23 10 24): canonical.
//   I-DEAS UNV (91 92 94 95 111 118): quadratic elements go round the element, corner and
//     mid-edge nodes alternating (tet: the base face, then the three edges to the apex,
//     then the apex), as Gmsh writes and reads them.
// Also the Abaqus face numbering of C3D4/C3D10: S1 = nodes 1-2-3, S2 = 1-4-2, S3 = 2-4-3,
// S4 = 3-4-1 (each listed so its right-hand normal points into the tetrahedron).
#include <array>

namespace aniso::io::order {

inline constexpr std::array<int, 10> kIdentity = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9};
inline constexpr std::array<int, 10> kGmshTet10 = {0, 1, 2, 3, 4, 5, 6, 7, 9, 8};
inline constexpr std::array<int, 6> kUnvTri6 = {0, 3, 1, 4, 2, 5};
inline constexpr std::array<int, 8> kUnvQuad8 = {0, 4, 1, 5, 2, 6, 3, 7};
inline constexpr std::array<int, 10> kUnvTet10 = {0, 4, 1, 5, 2, 6, 7, 8, 9, 3};

/// Abaqus tetrahedron faces S1..S4 as 0-based corner positions.
inline constexpr int kAbaqusTetFaces[4][3] = {{0, 1, 2}, {0, 3, 1}, {1, 3, 2}, {2, 3, 0}};

/// The Abaqus face number (1..4) of the tetrahedron face made of corners a, b, c (any
/// order), given the tetrahedron's four corners; 0 if they are not a face of it.
inline int abaqusFaceOf(const std::array<int, 4>& tet, int a, int b, int c) {
  for (int k = 0; k < 4; ++k) {
    int found = 0;
    for (int j : kAbaqusTetFaces[k]) {
      const int n = tet[j];
      found += (n == a) + (n == b) + (n == c);
    }
    if (found == 3) return k + 1;
  }
  return 0;
}

}  // namespace aniso::io::order
