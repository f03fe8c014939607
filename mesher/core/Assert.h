#pragma once
// ANISO_ASSERT(condition): a cheap precondition of the library (an index in range, a slot
// alive, an argument a header says "must" be so), checked where ANISOMESH_ASSERTS is defined
// — Debug builds and the sanitizer build (CMakeLists.txt, ANISOMESH_ASSERTS) — and compiled
// out otherwise: a Release build neither evaluates the condition nor changes its output.
//
// A violated precondition is a bug of the caller, not bad input nor a meshing failure: it
// throws AssertionError (never aborts, never prints, Error.h), which names the file, the
// line and the condition. It is a std::logic_error rather than a MeshingError so that no
// fallback that catches MeshingError (an entity left out, a retry) swallows it; the CLI
// reports it as an internal error (exit code 3).
//
// Do not use it in a noexcept function (the throw would terminate the program) nor for a
// condition with side effects (it is not evaluated in Release).
#include <stdexcept>
#include <string>

namespace aniso {

/// A violated ANISO_ASSERT: what() is "file:line: precondition failed: condition".
class AssertionError : public std::logic_error {
 public:
  AssertionError(const char* file, int line, const char* condition);
  const std::string& file() const { return file_; }
  int line() const { return line_; }
  const std::string& condition() const { return condition_; }

 private:
  std::string file_;
  int line_;
  std::string condition_;
};

/// Throws AssertionError(file, line, condition); out of line, so that the check inlined at
/// every use is one compare and one cold call.
[[noreturn]] void assertionFailed(const char* file, int line, const char* condition);

#if defined(ANISOMESH_ASSERTS)
inline constexpr bool kAssertsEnabled = true;
#define ANISO_ASSERT(condition) \
  (static_cast<bool>(condition) ? void(0) : ::aniso::assertionFailed(__FILE__, __LINE__, #condition))
#else
inline constexpr bool kAssertsEnabled = false;
// not evaluated; sizeof keeps the names "used" so that Release gets no unused warnings
#define ANISO_ASSERT(condition) static_cast<void>(sizeof(static_cast<bool>(condition)))
#endif

}  // namespace aniso
