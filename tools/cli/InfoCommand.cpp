#include <cstdio>

#include "cad/CadModel.h"
#include "tools/cli/Commands.h"
#include "tools/cli/ModelJson.h"

namespace aniso::cli {

int runInfo(const InfoArgs& args) {
  cad::CadModel model = cad::CadModel::read(args.file);
  const cad::ShapeSummary asRead = model.summary();
  cad::PrepareOptions popt;
  popt.fragment = args.fragment;
  const cad::PrepareReport prep = model.prepare(popt);
  const cad::ShapeSummary prepared = model.summary();

  if (args.json) {
    nlohmann::ordered_json j = summaryJson(asRead);
    j["file"] = args.file;
    j["format"] = cad::formatName(model.format());
    nlohmann::ordered_json p = summaryJson(prepared);
    p.update(prepareJson(prep));
    j["prepared"] = p;
    std::printf("%s\n", j.dump(1).c_str());
    return 0;
  }
  std::printf("%s (%s)\nas read:\n%s", args.file.c_str(), cad::formatName(model.format()),
              summaryText(asRead, "  ").c_str());
  std::printf("after preparation (fix, sew%s):\n%s", args.fragment ? ", fragment" : "",
              summaryText(prepared, "  ").c_str());
  if (prep.facesSewn) std::printf("  %d loose faces sewn\n", prep.facesSewn);
  if (prep.sharedFaces) std::printf("  %d faces shared by two solids\n", prep.sharedFaces);
  for (const auto& [a, b] : prep.overlappingSolids) std::printf("  solids %d and %d overlap\n", a, b);
  for (const auto& w : prep.warnings) std::printf("  warning: %s\n", w.c_str());
  return 0;
}

}  // namespace aniso::cli
