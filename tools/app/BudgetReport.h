#pragma once
// The element budget in the CLI (mesher/sizing/ElementBudget.h): the default limit from the
// machine's memory, and the report of what the budget did (report extra "budget", one
// warning line naming the coarsened faces).
#include "io/Report.h"
#include "mesher/sizing/ElementBudget.h"

namespace aniso::app {

/// The machine's physical memory: MemTotal of /proc/meminfo, else sysconf's physical pages;
/// 0 when unknown. Not the memory available now: that changes from run to run, and the
/// budget it gave would make the same input mesh differently (determinism).
double physicalMemoryBytes();

/// --max-elements when given (> 0), else defaultElementBudget(physicalMemoryBytes(), dim).
double elementBudget(double given, int dim);

/// report.extra["budget"] = {limit, predicted, triangles, tets, floor, predicted_after,
/// coarsened_faces: [1-based ids]}; a warning line when faces were coarsened.
void reportBudget(const ElementBudget& budget, io::Report& report);

}  // namespace aniso::app
