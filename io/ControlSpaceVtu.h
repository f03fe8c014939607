#pragma once
// Writes a control space structure (mesher/control/ControlSpaceGrid.h) as a VTK
// UnstructuredGrid (.vtu, ASCII) for ParaView: one VTK_QUAD (2D) or VTK_HEXAHEDRON (3D)
// per leaf, cell data "level", and at the points the tensor "metric" (M_s, 9 components),
// the scalars "h1" "h2" ("h3" in 3D) and the vectors "e1" "e2" ("e3") of the main
// directions, plus "Mp" when the parameterization tensor is cached. Points of a 2D control
// space are written at (u, v, 0). Atomic: nothing is left behind on failure.
#include <string>
#include <vector>

#include "mesher/control/ControlSpaceGrid.h"

namespace aniso::io {

/// `cellFace`, when given, is written as the cell data "face" (one CAD face id per cell).
void writeControlSpaceVtu(const ControlSpaceGrid& grid, const std::string& path,
                          const std::vector<int>* cellFace = nullptr);

}  // namespace aniso::io
