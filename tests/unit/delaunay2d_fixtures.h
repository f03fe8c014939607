#pragma once
// Shared helpers of the 2D kernel tests (delaunay2d_test.cpp, delaunay2d_ops_test.cpp):
// the unit box, the validator as a gtest expectation, the Delaunay check in a metric.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "mesher/delaunay/Validate2d.h"

namespace aniso::del2d::testing {

inline Box2 unitBox() {
  Box2 b;
  b.add(Vec2(0, 0));
  b.add(Vec2(1, 1));
  return b;
}

inline std::string joined(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += x + "\n";
  return s;
}

/// validate() with the Delaunay property checked in the metric of transform `m`.
inline ValidateOptions delaunayCheck(const Mat2& m = Mat2::Identity()) {
  ValidateOptions o;
  o.delaunay = true;
  o.transform = m;
  return o;
}

}  // namespace aniso::del2d::testing

/// The triangulation passes validate(tri, opts); the problems are printed otherwise.
#define EXPECT_VALID(tri, opts)                                                          \
  do {                                                                                   \
    const auto problems_ = ::aniso::del2d::validate(tri, opts);                          \
    EXPECT_TRUE(problems_.empty()) << ::aniso::del2d::testing::joined(problems_);        \
  } while (0)
