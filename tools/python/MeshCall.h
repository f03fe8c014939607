#pragma once
// anisomesh.mesh() and anisomesh.info() (docs/python.md): the keyword arguments as the
// CLI's MeshArgs (tools/app/MeshArgs.h) with the CLI's defaults, so that the same options
// give the CLI's mesh byte for byte; the run through tools/app/MeshRun.h in a worker thread
// (Worker.h). Errors: anisomesh.InputError (bad file or option; what the CLI exits 2 for),
// anisomesh.MeshingError (no mesh, a time limit; exit 3) with .problems (list of dicts as
// in the report) and .report (the run report, or None before the model was read).
#include <pybind11/pybind11.h>

namespace aniso::python {

/// Registers mesh(), info() and the exceptions Error, InputError, MeshingError in `m`.
void bindCalls(pybind11::module_& m);

}  // namespace aniso::python
