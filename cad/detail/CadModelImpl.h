#pragma once
// Internal: what a CadModel holds. Includes OCCT; only cad/ sources include this.
#include <TopoDS_Shape.hxx>
#include <TopTools_DataMapOfShapeInteger.hxx>
#include <TopTools_DataMapOfShapeReal.hxx>

#include <map>
#include <string>

#include "cad/CadModel.h"
#include "mesher/core/Cancel.h"

namespace aniso::cad {

/// What a STEP file (XCAF) says of one face: its name and its own colour, "" when it says
/// nothing. A colour the face would only inherit from its part or solid is not its colour.
struct FaceTag {
  std::string name;
  std::string color;  ///< "#rrggbb" (sRGB), or ""
};

struct CadModel::Impl {
  std::string path;
  CadFormat format = CadFormat::Step;
  TopoDS_Shape shape;
  /// Part names of solids from STEP/XCAF, keyed by the solid (TShape + location).
  TopTools_DataMapOfShapeInteger nameIndex;
  std::vector<std::string> names;  ///< "" for a part that has a colour but no name
  std::vector<std::string> partColors;  ///< parallel to names: "#rrggbb" or ""
  /// Face names and colours from STEP/XCAF, keyed by the face without its location (every
  /// instance of a part finds them); the preparation passes them on to the faces that
  /// replace a face (cad/detail/FaceTags.h).
  TopTools_DataMapOfShapeInteger faceTagIndex;
  std::vector<FaceTag> faceTags;
  /// What reading had to give up (a reader path that crashed, parts skipped); logged as
  /// warnings by CadModel::read.
  std::vector<std::string> readWarnings;
  /// Solids the STEP file declares that reading could not give as solids (not even rebuilt
  /// from their faces: lostSolids, Readers.h).
  int solidsLost = 0;
  /// Faces the STEP file holds (FACE entities, whether or not a shape uses them): says why a
  /// model that came out empty is empty.
  int facesInFile = 0;
  /// The length unit the file declares ("inch", "millimetre"; "" when it says none or is
  /// BREP); OCCT converts to mm on reading.
  std::string fileUnit;
  /// accurateVolume of the solids measured so far, keyed by the solid without its location
  /// (solidVolumeOf): summary() and topology() of one prepared shape integrate each part
  /// once, however many times the assembly places it.
  mutable TopTools_DataMapOfShapeReal volumes;
  /// The token of the operation under way (read, prepare): stops the child processes.
  const CancelToken* cancel = nullptr;

  /// Name of a solid: its part name if known, else "SOLID<id>".
  std::string solidName(const TopoDS_Shape& solid, int id) const;
  /// Colour of a solid's part ("#rrggbb"), "" when the file gives none.
  std::string solidColor(const TopoDS_Shape& solid) const;
  /// The tag of a face, null when the file says nothing of it.
  const FaceTag* faceTag(const TopoDS_Shape& face) const;
};

}  // namespace aniso::cad
