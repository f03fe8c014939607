#pragma once
// Internal: what a CadModel holds. Includes OCCT; only cad/ sources include this.
#include <TopoDS_Shape.hxx>
#include <TopTools_DataMapOfShapeInteger.hxx>

#include <map>
#include <string>

#include "cad/CadModel.h"
#include "mesher/core/Cancel.h"

namespace aniso::cad {

struct CadModel::Impl {
  std::string path;
  CadFormat format = CadFormat::Step;
  TopoDS_Shape shape;
  /// Part names of solids from STEP/XCAF, keyed by the solid (TShape + location).
  TopTools_DataMapOfShapeInteger nameIndex;
  std::vector<std::string> names;
  /// What reading had to give up (a reader path that crashed, parts skipped); logged as
  /// warnings by CadModel::read.
  std::vector<std::string> readWarnings;
  /// The token of the operation under way (read, prepare): stops the child processes.
  const CancelToken* cancel = nullptr;

  /// Name of a solid: its part name if known, else "SOLID<id>".
  std::string solidName(const TopoDS_Shape& solid, int id) const;
};

}  // namespace aniso::cad
