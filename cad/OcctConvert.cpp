#include "cad/detail/OcctConvert.h"

namespace aniso::cad::detail {

std::string occtMessage(const Standard_Failure& e) {
  const char* m = e.GetMessageString();
  return (m && *m) ? std::string(m) : std::string(e.DynamicType()->Name());
}

}  // namespace aniso::cad::detail
