#include "mesher/core/Assert.h"

namespace aniso {

AssertionError::AssertionError(const char* file, int line, const char* condition)
    : std::logic_error(std::string(file) + ":" + std::to_string(line) + ": precondition failed: " + condition),
      file_(file),
      line_(line),
      condition_(condition) {}

void assertionFailed(const char* file, int line, const char* condition) {
  throw AssertionError(file, line, condition);
}

}  // namespace aniso
