#pragma once
// FaceCatalog — every face and edge of a CAD model as a user needs it to find them in the
// mesh (`anisomesh info --faces`): the 1-based id (TopExp::MapShapes order of the current
// shape: after prepare(), the ids of the mesh's FACE<n> / EDGE<n> groups, FreeCAD's Face<n>),
// the geometry type, area or length, centroid and bounding box, the solids it bounds and
// its part name, and for a face what the STEP file says of it: its name and its own colour
// (XCAF sub-shape labels; a colour the face only inherits from its part or solid is not
// given here: the part's is in ShapeSummary's solid list). Names and colours follow the
// preparation's history to the faces that replace a face (cad/detail/FaceTags.h).
// OCCT-free header; measures in model units (mm for STEP and IGES).
#include <string>
#include <vector>

#include "cad/CadModel.h"

namespace aniso::cad {

struct CatalogEntry {
  int id = 0;            ///< 1-based
  std::string type;      ///< faces: plane cylinder cone sphere torus bezier bspline revolution
                         ///< extrusion offset other; edges: line circle ellipse hyperbola
                         ///< parabola bezier bspline offset other, degenerated (a pole)
  double measure = 0;    ///< area (faces) or length (edges)
  Vec3 centroid = Vec3::Zero();  ///< of the area or length (uniform density)
  Box3 bbox;
  std::vector<int> solids;  ///< 1-based, ascending; empty for a face of no solid
  std::vector<int> faces;   ///< edges only: the faces it bounds, 1-based, ascending
  std::string part;         ///< name of the first solid (solids.front()), "" when none
  std::string name;         ///< faces: the STEP face name, "" when none
  std::string color;        ///< faces: the face's own STEP colour "#rrggbb", "" when none
};

struct FaceCatalog {
  std::vector<CatalogEntry> faces, edges;
};

/// The catalog of the model's current shape (call after prepare() for the mesh's ids).
/// A face or edge OCCT cannot measure gets measure 0 and a zero centroid.
FaceCatalog faceCatalog(const CadModel& model);

}  // namespace aniso::cad
