#pragma once
// Internal: the preparation steps run by CadModel::prepare(), each its own operator.
// Every step keeps the part names of solids: it rebinds impl.nameIndex for the images.
#include <functional>

#include "cad/detail/CadModelImpl.h"

namespace aniso::cad::detail {

/// ShapeFix_Shape on the whole shape (wires, edges, faces, shells, solids).
void fixShape(CadModel::Impl& impl, double diag, PrepareReport& report);

/// Sews the faces that are not in a solid (loose faces, open shells) with tolerance
/// tol; keeps the result only if it leaves fewer free edges. Solids are not touched.
void sewLooseFaces(CadModel::Impl& impl, double tol, PrepareReport& report);

/// General fuse of the solids so that touching solids share their interface faces.
/// Overlapping solids are reported (ids as in the current shape) and then the shape is
/// left unfragmented: merging them would change the volume the user modelled.
void fragmentSolids(CadModel::Impl& impl, double diag, PrepareReport& report);

/// Number of edges (not degenerate) bounding exactly one face of the shape.
int countFreeEdges(const TopoDS_Shape& shape);

}  // namespace aniso::cad::detail

namespace aniso::cad::detail {

/// Runs one preparation step (fixShape, sewLooseFaces, fragmentSolids) in a child process
/// (ChildProcess.h), so that a crash of OCCT there costs the step, not the run: the shape
/// and the report are then kept as they were before the step, with a warning naming it.
/// `crashPoint` is the step's test hook (testCrashPoint), e.g. "prepare-fix".
void runPrepareStep(const char* step, const char* crashPoint, CadModel::Impl& impl, PrepareReport& report,
                    const std::function<void(CadModel::Impl&, PrepareReport&)>& run);

}  // namespace aniso::cad::detail
