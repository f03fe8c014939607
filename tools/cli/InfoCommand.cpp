#include <cstdio>
#include <string>

#include "cad/CadModel.h"
#include "io/AnalyticModel.h"
#include "tools/cli/Commands.h"
#include "tools/cli/FaceListing.h"
#include "tools/cli/ModelJson.h"

namespace aniso::cli {

namespace {

/// info on a .json analytic model: its topology and sizing (it needs no preparation).
int infoAnalytic(const InfoArgs& args) {
  const io::AnalyticModel am = io::readAnalyticModel(args.file);
  const Model& m = am.model;
  const Box3& b = m.bbox;
  if (args.json) {
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
    j["file"] = args.file;
    j["format"] = "analytic";
    j["name"] = am.name;
    j["holes"] = m.faces[0].loops.size() - 1;
    if (am.sizing) j["sizing"] = {{"angle", am.sizing->angle}, {"h1", am.sizing->h1}, {"h2", am.sizing->h2}};
    std::printf("%s\n", j.dump(1).c_str());
    return 0;
  }
  std::printf("%s (analytic model \"%s\")\n  faces 1, edges %zu, vertices %zu, holes %zu\n", args.file.c_str(),
              am.name.c_str(), m.edges.size(), m.vertices.size(), m.faces[0].loops.size() - 1);
  std::printf("  bounding box [%g, %g, %g] - [%g, %g, %g], diagonal %g\n", b.lo.x(), b.lo.y(), b.lo.z(), b.hi.x(),
              b.hi.y(), b.hi.z(), b.diagonal());
  if (am.sizing)
    std::printf("  sizing: angle %s, h1 %s, h2 %s\n", am.sizing->angle.c_str(), am.sizing->h1.c_str(),
                am.sizing->h2.c_str());
  return 0;
}

/// The unit of every length of the model (and of the mesh options): OCCT's STEP and IGES
/// readers convert to millimetres (xstep.cascade.unit, default MM); BREP stores no unit.
const char* lengthUnit(cad::CadFormat f) { return f == cad::CadFormat::Brep ? "file" : "mm"; }

}  // namespace

int runInfo(const InfoArgs& args) {
  if (io::isAnalyticModelPath(args.file)) return infoAnalytic(args);
  cad::CadModel model = cad::CadModel::read(args.file);
  const cad::ShapeSummary asRead = model.summary();
  cad::PrepareOptions popt;
  popt.fragment = args.fragment;
  popt.overlaps = args.overlaps;
  const cad::PrepareReport prep = model.prepare(popt);
  const cad::ShapeSummary prepared = model.summary();

  if (args.json) {
    nlohmann::ordered_json j = summaryJson(asRead);
    j["file"] = args.file;
    j["format"] = cad::formatName(model.format());
    j["units"] = lengthUnit(model.format());
    nlohmann::ordered_json p = summaryJson(prepared);
    p.update(prepareJson(prep));
    j["prepared"] = p;
    if (args.faces) j.update(catalogJson(cad::faceCatalog(model)));  // ids of the prepared model
    std::printf("%s\n", j.dump(1).c_str());
    return 0;
  }
  const bool mm = std::string(lengthUnit(model.format())) == "mm";
  std::printf("%s (%s, lengths in %s)\nas read:\n%s", args.file.c_str(), cad::formatName(model.format()),
              mm ? "mm: converted from the file's unit" : "the file's unit: BREP stores none", summaryText(asRead, "  ").c_str());
  std::printf("after preparation (fix, sew%s):\n%s", args.fragment ? ", fragment" : "",
              summaryText(prepared, "  ").c_str());
  if (prep.facesSewn) std::printf("  %d loose faces sewn\n", prep.facesSewn);
  if (prep.sharedFaces) std::printf("  %d faces shared by two solids\n", prep.sharedFaces);
  std::printf("%s", overlapsText(prep, "  ").c_str());
  for (const auto& w : prep.warnings) std::printf("  warning: %s\n", w.c_str());
  if (args.faces) std::printf("%s", catalogText(cad::faceCatalog(model)).c_str());
  return 0;
}

}  // namespace aniso::cli
