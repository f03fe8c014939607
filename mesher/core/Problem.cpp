#include "mesher/core/Problem.h"

namespace aniso {

const char* entityKindName(EntityKind k) {
  switch (k) {
    case EntityKind::Model: return "model";
    case EntityKind::Vertex: return "vertex";
    case EntityKind::Edge: return "edge";
    case EntityKind::Face: return "face";
    case EntityKind::Shell: return "shell";
    case EntityKind::Solid: return "solid";
  }
  return "model";
}

std::string entityName(const EntityRef& e) {
  if (e.kind == EntityKind::Model) return "model";
  return std::string(entityKindName(e.kind)) + " " + std::to_string(e.id);
}

std::string entityLabel(const EntityRef& e) {
  if (e.part.empty()) return entityName(e);
  return entityName(e) + " (part '" + e.part + "')";
}

const char* severityName(Severity s) {
  switch (s) {
    case Severity::Note: return "note";
    case Severity::Degraded: return "degraded";
    case Severity::Failed: return "failed";
  }
  return "failed";
}

const char* statusName(RunStatus s) {
  switch (s) {
    case RunStatus::Ok: return "ok";
    case RunStatus::Degraded: return "degraded";
    case RunStatus::Failed: return "failed";
  }
  return "failed";
}

RunStatus gradeRun(const std::vector<Problem>& problems, bool meshed) {
  if (!meshed) return RunStatus::Failed;
  for (const Problem& p : problems)
    if (p.severity != Severity::Note) return RunStatus::Degraded;
  return RunStatus::Ok;
}

const Problem* firstOf(const std::vector<Problem>& problems, Severity s) {
  for (const Problem& p : problems)
    if (p.severity == s) return &p;
  return nullptr;
}

}  // namespace aniso
