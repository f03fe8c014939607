#include "tools/app/ModelInput.h"

#include <algorithm>
#include <chrono>
#include <memory>

#include "cad/CadModel.h"
#include "mesher/control/CSAnalytic2d.h"
#include "mesher/core/Log.h"
#include "tools/app/ModelJson.h"

namespace aniso::app {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); }

}  // namespace

ModelInput loadModel(const std::string& file, bool fragment, cad::OverlapPolicy overlaps, const CancelToken* cancel) {
  ModelInput in;
  auto t = Clock::now();
  if (io::isAnalyticModelPath(file)) {
    io::AnalyticModel am = io::readAnalyticModel(file);
    in.times.emplace_back("read", since(t));
    in.analytic = true;
    in.analyticSizing = am.sizing;
    in.summary = {{"name", am.name}, {"faces", am.model.faces.size()}, {"edges", am.model.edges.size()},
                  {"analytic_sizing", am.sizing.has_value()}};
    in.model = std::move(am.model);
    return in;
  }
  auto phase = std::make_unique<Progress>("read", 0);  // a top-level phase of --progress
  in.cad = std::make_shared<cad::CadModel>(cad::CadModel::read(file, cancel));
  phase.reset();  // read ends before prepare begins (else prepare would nest in it)
  in.times.emplace_back("read", since(t));
  in.prepareOptions.fragment = fragment;
  in.prepareOptions.overlaps = overlaps;
  in.prepareOptions.cancel = cancel;
  prepareModel(in, file);
  return in;
}

void prepareModel(ModelInput& in, const std::string& file, const std::vector<std::string>& logged,
                  const char* prepareTime, const char* topologyTime) {
  auto phase = std::make_unique<Progress>(prepareTime, 0);
  auto t = Clock::now();
  in.prepared = in.cad->prepare(in.prepareOptions);
  const cad::PrepareReport& prep = in.prepared;
  const cad::ShapeSummary summary = in.cad->summary();
  in.times.emplace_back(prepareTime, since(t));
  phase.reset();
  for (const std::string& w : prep.warnings)
    if (std::find(logged.begin(), logged.end(), w) == logged.end()) logWarning(file + ": " + w);
  in.solids = summary.solids;
  in.summary = summaryJson(summary);
  in.summary.update(prepareJson(prep));
  t = Clock::now();
  in.model = in.cad->topology();
  in.times.emplace_back(topologyTime, since(t));
  in.problems.clear();
  for (const int id : prep.unfusedSolids) {
    const std::string part =
        id >= 1 && id <= static_cast<int>(in.model.solids.size()) ? in.model.solids[id - 1].name : std::string();
    in.problems.push_back({EntityRef{EntityKind::Solid, id, part}, Severity::Degraded, "not-fragmented",
                           "the fuse with the other parts failed on it: meshed on its own, not conformal with the "
                           "parts it touches",
                           "prepare"});
  }
}

std::unique_ptr<ControlSpace2d> analyticControlSpace(const ModelInput& in) {
  if (!in.analyticSizing) return nullptr;
  const io::AnalyticSizing& s = *in.analyticSizing;
  const ModelFace& f = in.model.faces.at(0);
  return std::make_unique<CSAnalytic2d>(f.uvBounds, s.angle, s.h1, s.h2);
}

}  // namespace aniso::app
