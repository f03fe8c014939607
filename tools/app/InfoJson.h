#pragma once
// infoJson — what `anisomesh info --json` prints and `anisomesh.info()` returns: the
// model's counts, volume, area, bounding box and solids (with their part names) as read,
// then the same after preparation ("prepared", with what the preparation did); with
// `faces`, every face and edge of the prepared model (FaceListing.h). A .json analytic
// model gives its topology and sizing instead. Throws InputError for a bad file.
#include <nlohmann/json.hpp>

#include <string>

#include "cad/CadModel.h"

namespace aniso::app {

struct InfoRequest {
  std::string file;
  bool faces = false;     ///< also "face_list" and "edge_list"
  bool fragment = true;   ///< the preparation fragments touching solids
  cad::OverlapPolicy overlaps = cad::OverlapPolicy::Merge;
};

/// A CAD file read (its summary as read) and prepared as `info` does it.
struct InfoModel {
  cad::CadModel model;
  cad::ShapeSummary asRead;
  cad::PrepareReport prepare;
};
InfoModel readInfoModel(const InfoRequest& request);

nlohmann::ordered_json infoJson(const InfoRequest& request);

/// The unit of every length of the model (and of the mesh options): OCCT's STEP and IGES
/// readers convert to millimetres (xstep.cascade.unit, default MM); BREP stores no unit.
const char* lengthUnit(cad::CadFormat f);

/// How the model's lengths came to be in lengthUnit, for people: "mm", "mm, converted from
/// inch" (the file's own unit, CadModel::fileUnit), "the file's unit: BREP stores none".
std::string unitsPhrase(cad::CadFormat f, const std::string& fileUnit);

}  // namespace aniso::app
