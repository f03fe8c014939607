// The Python module `anisomesh` (docs/python.md): mesh(), info(), Mesh and the exceptions.
#include <pybind11/pybind11.h>

#include "tools/python/MeshCall.h"
#include "tools/python/MeshObject.h"

PYBIND11_MODULE(anisomesh, m) {
  m.doc() = "anisomesh: triangle, quad and tetrahedral meshes of CAD models (STEP, IGES, BREP)";
  m.attr("__version__") = ANISOMESH_VERSION;
  aniso::python::bindMesh(m);
  aniso::python::bindCalls(m);
}
