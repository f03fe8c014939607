#pragma once
// Problem — one shortcoming of a run, named by the CAD entity it concerns, and the grade of
// the whole run that the problems add up to (STYLE.md §10; MMG's SUCCESS / LOWFAILURE /
// STRONGFAILURE is the anchor).
//
// Grading policy (gradeRun):
//   Ok       — a mesh of every entity that was asked for, no problem of severity Degraded
//              or Failed.
//   Degraded — a valid mesh is written, with named shortcomings: a face or solid left out
//              (its problems say why), a face meshed across a gap in its CAD boundary, a
//              budget that coarsened the sizing, quality left below the bar. The CLI exits
//              0 and prints a warning; the report lists every problem.
//   Failed   — nothing usable: no mesh is written, the CLI exits 3 naming the first
//              problem of severity Failed.
// Severity of a problem is about its entity: Note (information, e.g. a healed gap within
// the CAD tolerance), Degraded (the entity is meshed, but not as asked), Failed (the entity
// has no mesh). A run with entities Failed but a mesh of the others is Degraded.
#include <string>
#include <vector>

namespace aniso {

enum class EntityKind { Model, Vertex, Edge, Face, Shell, Solid };

/// A CAD entity by its 1-based id (the numbering of Model.h: OCCT MapShapes order, FreeCAD's
/// FaceN, Gmsh's OCC kernel). id 0 with kind Model means the whole model.
struct EntityRef {
  EntityKind kind = EntityKind::Model;
  int id = 0;        ///< 1-based
  std::string part;  ///< name of the part (solid) it belongs to, when known

  static EntityRef model() { return {}; }
  static EntityRef face(int index0, std::string part = {}) { return {EntityKind::Face, index0 + 1, std::move(part)}; }
  static EntityRef edge(int index0) { return {EntityKind::Edge, index0 + 1, {}}; }
  static EntityRef solid(int index0, std::string part = {}) { return {EntityKind::Solid, index0 + 1, std::move(part)}; }
  static EntityRef shell(int index0) { return {EntityKind::Shell, index0 + 1, {}}; }
  static EntityRef vertex(int index0) { return {EntityKind::Vertex, index0 + 1, {}}; }
};

/// "face 12", "solid 3", "model": the one formatter of entity names.
std::string entityName(const EntityRef& e);
/// "face 12 (part 'bracket')" when the part is known, else entityName.
std::string entityLabel(const EntityRef& e);
const char* entityKindName(EntityKind k);

enum class Severity { Note, Degraded, Failed };
const char* severityName(Severity s);

struct Problem {
  EntityRef entity;
  Severity severity = Severity::Failed;
  std::string code;    ///< short stable identifier, e.g. "loop-open", "face-mesh", "solid-mesh"
  std::string detail;  ///< one sentence in plain words
  std::string where;   ///< the phase that found it: "model", "surface", "volume", ...
};

enum class RunStatus { Ok, Degraded, Failed };
const char* statusName(RunStatus s);

/// The grade of a run (see the policy above): `meshed` says whether a mesh exists to write.
RunStatus gradeRun(const std::vector<Problem>& problems, bool meshed);

/// The first problem of the given severity, or null.
const Problem* firstOf(const std::vector<Problem>& problems, Severity s);

}  // namespace aniso
