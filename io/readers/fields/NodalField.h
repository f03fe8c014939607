#pragma once
// NodalField — one scalar per node of a mesh file, chosen from its data arrays: what the
// adapt command turns into a metric (issue 19). Any format readMesh reads that carries
// data: MSH $NodeData / $ElementData, VTU PointData / CellData, CalculiX .frd results.
//
// The selection `spec` is NAME or NAME:COMPONENT (the name exact, else ignoring case):
//   a scalar array                      its value
//   a vector (2 or 3 components)        the magnitude; :x :y :z or :0 :1 :2 one component
//   a symmetric tensor (6 components, xx yy zz xy yz zx as FRD and VTK write them) or a
//   full one (9, row-major)             the von Mises stress; :mises, :p1 :p2 :p3 the
//                                       principal values (p1 ≥ p2 ≥ p3), :xx ... :zx
//   any array                           :N (0-based) or a component name the file gives
//                                       (FRD: D1, SXX ...)
// Element data is averaged to the nodes (each element's value counts once at each of its
// nodes; elements without a value are left out).
//
// Throws InputError with one line naming the file: no data arrays in the file (an FRD
// without results), an unknown name (listing the available ones), an unknown component, a
// non-finite value (NaN, inf, or a node the field gives no value).
#include <string>
#include <vector>

#include "io/readers/ReadMesh.h"

namespace aniso::io {

struct NodalField {
  std::string name;            ///< the spec, as given
  std::vector<double> values;  ///< one per node of the mesh
  /// The whole array the spec names (all its components, element data averaged as above):
  /// what `adapt --transfer` carries to the new mesh. Node-major, `components` per node.
  std::string arrayName;
  int components = 1;
  std::vector<double> arrayValues;
};

/// The selected scalar of `mesh`, read from `path` (named in the messages).
NodalField selectField(const ReadMesh& mesh, const std::string& spec, const std::string& path);

/// Von Mises stress and principal values of a symmetric tensor (xx yy zz xy yz zx).
double vonMises(const double* s6);
void principalValues(const double* s6, double out[3]);

}  // namespace aniso::io
