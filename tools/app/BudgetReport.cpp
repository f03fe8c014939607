#include "tools/app/BudgetReport.h"

#include <unistd.h>

#include <fstream>
#include <string>

#include "mesher/core/Log.h"
#include "mesher/sizing/SurfaceBudget.h"

namespace aniso::app {

double physicalMemoryBytes() {
  std::ifstream in("/proc/meminfo");
  std::string key;
  double kb = 0;
  std::string unit;
  while (in >> key >> kb >> unit)
    if (key == "MemTotal:") return kb * 1024.0;
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  return pages > 0 && page > 0 ? static_cast<double>(pages) * static_cast<double>(page) : 0.0;
}

double elementBudget(double given, int dim) {
  if (given > 0) return given;
  const double bytes = physicalMemoryBytes();
  return bytes > 0 ? defaultElementBudget(bytes, dim) : 0.0;  // unknown memory: no budget
}

void reportBudget(const ElementBudget& b, io::Report& report) {
  nlohmann::ordered_json faces = nlohmann::ordered_json::array();
  for (const BudgetCoarsening& c : b.coarsened) faces.push_back(c.face + 1);
  report.extra["budget"] = {{"limit", b.limit},       {"predicted", b.predicted}, {"triangles", b.triangles},
                            {"tets", b.tets},         {"floor", b.floor},         {"predicted_after", b.predictedAfter},
                            {"coarsened_faces", faces}};
  if (!b.coarsened.empty()) logWarning(budgetWarning(b));
}

}  // namespace aniso::app
