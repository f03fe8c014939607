#pragma once
// The one way the kernel maps a point to metric space, P^M = M P (thesis eq. 2.17):
// Inserter, EnclosingBox and validate() all use it, so the exact predicates see bit-for-bit
// the same transformed coordinates everywhere.
#include "mesher/core/Types.h"

namespace aniso::del3d {

inline void transformPoint(const Mat3& m, const double* x, double* out) {
  for (int r = 0; r < 3; ++r) out[r] = m(r, 0) * x[0] + m(r, 1) * x[1] + m(r, 2) * x[2];
}

}  // namespace aniso::del3d
