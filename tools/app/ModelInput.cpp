#include "tools/app/ModelInput.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>

#include "cad/CadModel.h"
#include "cad/OverlapRule.h"
#include "mesher/control/CSAnalytic2d.h"
#include "mesher/core/Log.h"
#include "tools/app/ModelJson.h"

namespace aniso::app {
namespace {

/// The prepared solids may differ from the solids as read, less the overlaps merged, by this
/// fraction of their volume before the run is degraded (`volume-changed`): the referee's
/// bar on a mesh's volume is 1 %.
constexpr double kPreparedVolumeRel = 0.01;

std::string formatted(const char* format, double v) {
  char buf[48];
  std::snprintf(buf, sizeof buf, format, v);
  return buf;
}

}  // namespace

ModelInput loadModel(const std::string& file, bool fragment, cad::OverlapPolicy overlaps, const CancelToken* cancel) {
  using Clock = std::chrono::steady_clock;
  auto since = [](Clock::time_point a) { return std::chrono::duration<double>(Clock::now() - a).count(); };
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
  cad::CadModel model = cad::CadModel::read(file, cancel);
  phase.reset();  // read ends before prepare begins (else prepare would nest in it)
  phase = std::make_unique<Progress>("prepare", 0);
  in.times.emplace_back("read", since(t));
  t = Clock::now();
  const double volumeRead = model.summary().volume;
  cad::PrepareOptions popt;
  popt.fragment = fragment;
  popt.overlaps = overlaps;
  popt.cancel = cancel;
  const cad::PrepareReport prep = model.prepare(popt);
  const cad::ShapeSummary summary = model.summary();
  in.times.emplace_back("prepare", since(t));
  phase.reset();
  for (const std::string& w : prep.warnings) logWarning(file + ": " + w);
  in.solids = summary.solids;
  in.summary = summaryJson(summary);
  in.summary.update(prepareJson(prep));
  in.summary["file_unit"] = model.fileUnit();
  t = Clock::now();
  in.model = model.topology();
  in.times.emplace_back("topology", since(t));
  if (model.solidsLost() > 0)  // a declared solid meshed as loose faces, or not at all
    in.problems.push_back({EntityRef{EntityKind::Model, 0, ""}, Severity::Degraded, "solid-not-read",
                           std::to_string(model.solidsLost()) +
                               " solid(s) the file declares could not be read as solids: their faces, if "
                               "any were read, are meshed as surfaces, with no tetrahedra inside",
                           "read"});
  // the repairs must keep the solids' volume, less the overlaps merged (counted once), and
  // less what a solid overlapping itself counted twice
  const double volumeError =
      cad::preparedVolumeError(volumeRead - prep.selfOverlapVolume, summary.volume, prep.overlaps);
  if (std::abs(volumeError) > kPreparedVolumeRel)
    in.problems.push_back({EntityRef{EntityKind::Model, 0, ""}, Severity::Degraded, "volume-changed",
                           "preparing the model changed the solids' volume by " + formatted("%+.2f", 100 * volumeError) +
                               " % (from " + formatted("%.6g", volumeRead) + " as read to " + formatted("%.6g", summary.volume) +
                               ", overlaps counted once): a repair lost or added geometry",
                           "prepare"});
  for (const int id : prep.unfusedSolids) {
    const std::string part =
        id >= 1 && id <= static_cast<int>(in.model.solids.size()) ? in.model.solids[id - 1].name : std::string();
    in.problems.push_back({EntityRef{EntityKind::Solid, id, part}, Severity::Degraded, "not-fragmented",
                           "the fuse with the other parts failed on it: meshed on its own, not conformal with the "
                           "parts it touches",
                           "prepare"});
  }
  return in;
}

std::unique_ptr<ControlSpace2d> analyticControlSpace(const ModelInput& in) {
  if (!in.analyticSizing) return nullptr;
  const io::AnalyticSizing& s = *in.analyticSizing;
  const ModelFace& f = in.model.faces.at(0);
  return std::make_unique<CSAnalytic2d>(f.uvBounds, s.angle, s.h1, s.h2);
}

}  // namespace aniso::app
