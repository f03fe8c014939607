#include <cstdio>
#include <string>

#include "cad/CadModel.h"
#include "io/AnalyticModel.h"
#include "tools/app/FaceListing.h"
#include "tools/app/InfoJson.h"
#include "tools/app/ModelJson.h"
#include "tools/cli/Commands.h"

namespace aniso::cli {

namespace {

/// info on a .json analytic model: its topology and sizing (it needs no preparation).
int infoAnalytic(const InfoArgs& args) {
  const io::AnalyticModel am = io::readAnalyticModel(args.file);
  const Model& m = am.model;
  const Box3& b = m.bbox;
  std::printf("%s (analytic model \"%s\")\n  faces 1, edges %zu, vertices %zu, holes %zu\n", args.file.c_str(),
              am.name.c_str(), m.edges.size(), m.vertices.size(), m.faces[0].loops.size() - 1);
  std::printf("  bounding box [%g, %g, %g] - [%g, %g, %g], diagonal %g\n", b.lo.x(), b.lo.y(), b.lo.z(), b.hi.x(),
              b.hi.y(), b.hi.z(), b.diagonal());
  if (am.sizing)
    std::printf("  sizing: angle %s, h1 %s, h2 %s\n", am.sizing->angle.c_str(), am.sizing->h1.c_str(),
                am.sizing->h2.c_str());
  return 0;
}

}  // namespace

int runInfo(const InfoArgs& args) {
  if (args.json) {
    std::printf("%s\n", app::infoJson({args.file, args.faces, args.fragment, args.overlaps}).dump(1).c_str());
    return 0;
  }
  if (io::isAnalyticModelPath(args.file)) return infoAnalytic(args);
  const app::InfoModel m = app::readInfoModel({args.file, args.faces, args.fragment, args.overlaps});
  const cad::CadModel& model = m.model;
  const cad::ShapeSummary& asRead = m.asRead;
  const cad::PrepareReport& prep = m.prepare;
  const cad::ShapeSummary prepared = model.summary();

  std::printf("%s (%s, lengths in %s)\nas read:\n%s", args.file.c_str(), cad::formatName(model.format()),
              app::unitsPhrase(model.format(), model.fileUnit()).c_str(), app::summaryText(asRead, "  ").c_str());
  std::printf("after preparation (fix, sew%s):\n%s", args.fragment ? ", fragment" : "",
              app::summaryText(prepared, "  ").c_str());
  if (prep.facesSewn) std::printf("  %d loose faces sewn\n", prep.facesSewn);
  if (prep.sharedFaces) std::printf("  %d faces shared by two solids\n", prep.sharedFaces);
  std::printf("%s", app::overlapsText(prep, "  ").c_str());
  for (const auto& w : prep.warnings) std::printf("  warning: %s\n", w.c_str());
  if (args.faces) std::printf("%s", app::catalogText(cad::faceCatalog(model)).c_str());
  return 0;
}

}  // namespace aniso::cli
