#pragma once
// The surface mesh of a test model at a given h_max (one thread), checked to be made.
#include <gtest/gtest.h>

#include "mesher/pipeline/SurfaceMesher.h"

namespace aniso::test {

inline SurfaceMesh meshModel(const Model& m, double hmax) {
  SurfaceMesherInput in;
  in.model = &m;
  in.options.sizing.hmax = hmax;
  in.options.threads = 1;
  SurfaceMeshResult r = meshSurfaces(in);
  EXPECT_TRUE(r.ok());
  EXPECT_FALSE(r.mesh.triangles.empty());
  return std::move(r.mesh);
}

}  // namespace aniso::test
