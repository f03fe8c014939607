#pragma once
// `anisomesh info --faces`: the faces and edges of the prepared model (cad/FaceCatalog.h)
// as JSON or as a table, so that a user finds which FACE<n> group of the mesh is which.
#include <nlohmann/json.hpp>

#include <string>

#include "cad/FaceCatalog.h"

namespace aniso::app {

/// {"face_list": [{"id", "type", "area", "centroid": [x,y,z], "bbox": {"min","max"},
///   "solids": [...], "part", "name" and "color" ("#rrggbb") when the STEP file gives the
///   face a name or a colour}], "edge_list": [{"id", "type", "length", "centroid", "bbox",
///   "faces": [...], "solids": [...], "part"}]}
nlohmann::ordered_json catalogJson(const cad::FaceCatalog& c);

/// One line per face, then per edge: id, type, area or length, centroid, solids, part;
/// a face's STEP name and colour after them when it has them.
std::string catalogText(const cad::FaceCatalog& c);

}  // namespace aniso::app
