#include "tools/cli/BudgetReport.h"

#include <unistd.h>

#include <cstdio>
#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>

#include "mesher/core/Log.h"

namespace aniso::cli {
namespace {

std::string count(double x) { return std::to_string(static_cast<long long>(std::llround(std::min(x, 1e18)))); }

std::string g3(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", x);
  return text;
}

}  // namespace

double availableMemoryBytes() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kb = 0;
  std::string unit;
  while (in >> key >> kb >> unit)
    if (key == "MemAvailable:") return kb * 1024.0;
  const long pages = sysconf(_SC_AVPHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0.0;
}

double elementBudget(double given, int dim) {
  if (given > 0) return given;
  const double bytes = availableMemoryBytes();
  return bytes > 0 ? defaultElementBudget(bytes, dim) : 0.0;  // unknown memory: no budget
}

void reportBudget(const ElementBudget& b, io::Report& report) {
  nlohmann::ordered_json faces = nlohmann::ordered_json::array();
  for (const BudgetCoarsening& c : b.coarsened) faces.push_back(c.face + 1);
  report.extra["budget"] = {{"limit", b.limit},       {"predicted", b.predicted}, {"triangles", b.triangles},
                            {"tets", b.tets},         {"floor", b.floor},         {"predicted_after", b.predictedAfter},
                            {"coarsened_faces", faces}};
  if (b.coarsened.empty()) return;
  std::string names;
  const std::size_t shown = std::min<std::size_t>(b.coarsened.size(), 10);
  for (std::size_t i = 0; i < shown; ++i) names += (i ? ", " : "") + std::to_string(b.coarsened[i].face + 1);
  if (shown < b.coarsened.size()) names += " and " + std::to_string(b.coarsened.size() - shown) + " more";
  logWarning("the sizing asks for " + count(b.predicted) + " elements, over the budget of " + count(b.limit) + " (--max-elements): face" +
             (b.coarsened.size() > 1 ? "s " : " ") + names + " coarsened to sizes of at least " + g3(b.floor) + " (" +
             count(b.predictedAfter) + " elements predicted)");
}

}  // namespace aniso::cli
