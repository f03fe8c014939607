#pragma once
// ControlSpaceGrid — a control space structure exported for visualisation (e.g. a VTU
// file with one cell per quadtree/octree leaf or background-mesh element and tensor
// fields at the points). Produced by CSQuadtree2d::grid(), CSOctree3d::grid(),
// CSMesh2d::grid() and CSMesh3d::grid(); writing files is left to io/.
//
// Layout (flat arrays, STYLE.md 3):
//   points          every control vertex, 2D points as (u, v, 0);
//   cells           cellSize vertex ids per cell in VTK order. The cell type follows from
//                   (dim, cellSize):
//                     tree leaves     VTK_QUAD (2, 4), VTK_HEXAHEDRON (3, 8); extra
//                                     ("hanging") vertices of a leaf are points but not
//                                     part of its cell;
//                     background mesh VTK_TRIANGLE (2, 3), counter-clockwise;
//                                     VTK_TETRA (3, 4), positively oriented ((0, 1, 2)
//                                     counter-clockwise seen from 3); the kernel's box
//                                     corners and their elements are included;
//   cellLevel       tree level of each leaf; 0 for background-mesh elements;
//   per point, when the control space carries metrics (else these are empty):
//     metric        transformation tensor M_s (2D: upper-left 2×2 block, rest 0),
//     lengths       requested lengths h_i, ascending (2D: third entry 0),
//     directions    columns e_i matching lengths (2D: third column (0, 0, 1));
//   parameterization  2D only, when M_p is cached (adaptToParameterization): M_p per
//                   point in the upper-left block, else empty.
#include <vector>

#include "mesher/core/Types.h"

namespace aniso {

struct ControlSpaceGrid {
  int dim = 2;
  int cellSize = 4;
  std::vector<Vec3> points;
  std::vector<int> cells;
  std::vector<int> cellLevel;
  std::vector<Mat3> metric;
  std::vector<Vec3> lengths;
  std::vector<Mat3> directions;
  std::vector<Mat3> parameterization;

  std::size_t cellCount() const { return cellLevel.size(); }
};

}  // namespace aniso
