#pragma once
// FaceCatalog — every face and edge of a CAD model as a user needs it to find them in the
// mesh (`anisomesh info --faces`): the 1-based id (TopExp::MapShapes order of the current
// shape: after prepare(), the ids of the mesh's FACE<n> / EDGE<n> groups, FreeCAD's Face<n>),
// the geometry type, area or length, centroid and bounding box, the solids it bounds and
// its part name. (STEP face names and colours are not read yet: XCAF's sub-shape labels
// would have to cross the reader's child process and follow the preparation's history.)
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
};

struct FaceCatalog {
  std::vector<CatalogEntry> faces, edges;
};

/// The catalog of the model's current shape (call after prepare() for the mesh's ids).
/// A face or edge OCCT cannot measure gets measure 0 and a zero centroid.
FaceCatalog faceCatalog(const CadModel& model);

}  // namespace aniso::cad
