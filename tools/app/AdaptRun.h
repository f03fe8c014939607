#pragma once
// adaptFile — the adapt run of a program (the CLI's `adapt`, the Python module's adapt())
// up to the mesh in memory (issue 19): the solver's mesh and its field read (io), the CAD
// model read and prepared once, adaptModel (mesher/adapt/AdaptModel.h) called and the run
// report filled with its "adapt" block. Writing is the caller's. The same AdaptArgs give
// the same mesh, byte for byte, through either program.
#include <string>

#include <nlohmann/json.hpp>

#include "io/readers/ReadMesh.h"
#include "io/readers/fields/NodalField.h"
#include "io/Report.h"
#include "mesher/adapt/AdaptModel.h"
#include "mesher/adapt/HessianRecovery.h"
#include "tools/app/MeshArgs.h"
#include "tools/app/ModelInput.h"

namespace aniso::app {

struct AdaptArgs {
  MeshArgs mesh;           ///< model, output, report, order, sizing options (γ_a default 10)
  std::string from;        ///< the solver's mesh with the field (.msh .vtu .frd .inp)
  std::string field;       ///< NAME or NAME:COMPONENT (io/readers/fields/NodalField.h)
  double targetNodes = 0;  ///< the output's node count asked; 0: that of `from` (unless error)
  double error = 0;        ///< the Lp interpolation error asked instead
  double norm = 2;         ///< p of the Lp norm
  HessianMethod hessian = HessianMethod::LeastSquares;
};

/// The solver's mesh and the field as the adaptation uses them.
struct FieldInput {
  io::ReadMesh mesh;
  io::NodalField field;
  PatchMesh patch;         ///< the cells of mesh's top dimension
  FieldHessians hessians;
};

/// Checks the options that need no file (InputError: both a count and an error, p < 1,
/// γ_a < 1), reads `from` and selects the field (InputError naming the file: unreadable, no
/// such field, NaN, no cells). Done before the model is read, so a bad field fails fast.
FieldInput readField(const AdaptArgs& args);

struct AdaptRun {
  ModelInput input;
  AdaptResult result;  ///< result.mesh.meshed() false: no mesh (failureMessage says why)
};

/// As meshFile (MeshRun.h), with the field's metric: args.mesh's dim 0 becomes the field
/// mesh's and γ_a holds in the volume too; the report gets the "adapt" block (the metric,
/// and for a count asked the rounds' outcome). Throws InputError (FieldError reworded with
/// the file's name) and Cancelled.
AdaptRun adaptFile(AdaptArgs& args, const FieldInput& field, io::Report& report);

}  // namespace aniso::app
