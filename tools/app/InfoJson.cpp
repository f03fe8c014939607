#include "tools/app/InfoJson.h"

#include "io/AnalyticModel.h"
#include "tools/app/FaceListing.h"
#include "tools/app/ModelJson.h"

namespace aniso::app {
namespace {

/// A .json analytic model: its topology and sizing (it needs no preparation).
nlohmann::ordered_json analyticJson(const std::string& file) {
  const io::AnalyticModel am = io::readAnalyticModel(file);
  const Model& m = am.model;
  const Box3& b = m.bbox;
  nlohmann::ordered_json j;
  j["solids"] = 0;
  j["shells"] = 0;
  j["faces"] = m.faces.size();
  j["edges"] = m.edges.size();
  j["vertices"] = m.vertices.size();
  j["volume"] = 0.0;
  j["area"] = nullptr;  // not integrated for analytic patches
  j["bbox"] = {{"min", {b.lo.x(), b.lo.y(), b.lo.z()}}, {"max", {b.hi.x(), b.hi.y(), b.hi.z()}},
               {"diagonal", b.diagonal()}};
  j["file"] = file;
  j["format"] = "analytic";
  j["name"] = am.name;
  j["holes"] = m.faces[0].loops.size() - 1;
  if (am.sizing) j["sizing"] = {{"angle", am.sizing->angle}, {"h1", am.sizing->h1}, {"h2", am.sizing->h2}};
  return j;
}

}  // namespace

const char* lengthUnit(cad::CadFormat f) { return f == cad::CadFormat::Brep ? "file" : "mm"; }

std::string unitsPhrase(cad::CadFormat f, const std::string& fileUnit) {
  if (f == cad::CadFormat::Brep) return "the file's unit: BREP stores none";
  if (fileUnit.empty() || fileUnit == "millimetre" || fileUnit == "mm") return "mm";
  return "mm, converted from " + fileUnit;
}

InfoModel readInfoModel(const InfoRequest& r) {
  InfoModel m{cad::CadModel::read(r.file), {}, {}};
  m.asRead = m.model.summary();
  cad::PrepareOptions popt;
  popt.fragment = r.fragment;
  popt.overlaps = r.overlaps;
  m.prepare = m.model.prepare(popt);
  return m;
}

nlohmann::ordered_json infoJson(const InfoRequest& r) {
  if (io::isAnalyticModelPath(r.file)) return analyticJson(r.file);
  const InfoModel m = readInfoModel(r);
  const cad::CadModel& model = m.model;
  nlohmann::ordered_json j = summaryJson(m.asRead);
  j["file"] = r.file;
  j["format"] = cad::formatName(model.format());
  j["units"] = lengthUnit(model.format());
  j["file_unit"] = model.fileUnit();
  nlohmann::ordered_json p = summaryJson(model.summary());
  p.update(prepareJson(m.prepare));
  j["prepared"] = p;
  if (r.faces) j.update(catalogJson(cad::faceCatalog(model)));  // ids of the prepared model
  return j;
}

}  // namespace aniso::app
