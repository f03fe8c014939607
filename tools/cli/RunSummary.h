#pragma once
// What a successful mesh run tells its user on stderr (issue 17, "a run that speaks";
// Gmsh's last lines are the model): input and units, parts, elements by type, shape
// quality (min/mean mean ratio, smallest angle, a histogram), time, output and its size,
// then the warnings in plain words — overlapping parts merged, thin walls refined, sizes
// coarsened by the element budget, entities left out or degraded (1-based ids, part names).
// Everything comes from the run report (io/Report.h), so the summary and --report agree.
// Printed as notices (mesher/core/Log.h): -q silences it.
#include <string>
#include <vector>

#include "io/Report.h"

namespace aniso::cli {

/// Problems of severity Degraded or Failed listed one per line; beyond, a count.
inline constexpr int kSummaryMaxProblems = 10;

struct RunSummaryText {
  std::vector<std::string> lines;     ///< facts: input, elements, quality, histogram, output
  std::vector<std::string> warnings;  ///< plain-word warnings
};

/// The summary of a run whose mesh was written to `output` (its size is read from disk).
RunSummaryText runSummary(const io::Report& report, const std::string& output);

/// runSummary() as notices and warnings.
void printRunSummary(const io::Report& report, const std::string& output);

}  // namespace aniso::cli
