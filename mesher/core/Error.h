#pragma once
// Errors of the library. Library code never prints and never exits: it throws one of
// these, and the CLI turns them into a one-line message and an exit code.
#include <stdexcept>
#include <string>

#include "mesher/core/Problem.h"

namespace aniso {

/// The input is unusable (missing, unreadable, not CAD, empty, bad option): exit code 2.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Meshing (or a geometric operation the mesher asked for) failed: exit code 3.
class MeshingError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A meshing failure confined to one CAD entity (e.g. an edge that cannot be discretized):
/// the caller may leave that entity and what depends on it out and go on.
class EntityError : public MeshingError {
 public:
  EntityError(EntityKind kind, int index0, const std::string& what)
      : MeshingError(what), kind_(kind), index_(index0) {}
  EntityKind kind() const { return kind_; }
  int index() const { return index_; }  ///< 0-based

 private:
  EntityKind kind_;
  int index_;
};

}  // namespace aniso
