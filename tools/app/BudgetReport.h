#pragma once
// The element budget in the CLI (mesher/sizing/ElementBudget.h): the default limit from the
// machine's memory, and the report of what the budget did (report extra "budget", one
// warning line naming the coarsened faces).
#include "io/Report.h"
#include "mesher/sizing/ElementBudget.h"

namespace aniso::app {

/// MemAvailable of /proc/meminfo; else the free physical pages (sysconf); 0 when unknown.
double availableMemoryBytes();

/// --max-elements when given (> 0), else defaultElementBudget(availableMemoryBytes(), dim).
double elementBudget(double given, int dim);

/// report.extra["budget"] = {limit, predicted, triangles, tets, floor, predicted_after,
/// coarsened_faces: [1-based ids]}; a warning line when faces were coarsened.
void reportBudget(const ElementBudget& budget, io::Report& report);

}  // namespace aniso::app
