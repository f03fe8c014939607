#pragma once
// Errors of the library. Library code never prints and never exits: it throws one of
// these, and the CLI turns them into a one-line message and an exit code.
#include <stdexcept>
#include <string>

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

}  // namespace aniso
