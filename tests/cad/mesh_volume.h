#pragma once
// The volume a tetrahedral mesh encloses (the sum of its tets' signed volumes), for the CAD
// tests that compare it with the solid's.
#include <Eigen/Geometry>

#include "mesher/volume/VolumeMesh.h"

namespace aniso {

inline double meshVolume(const VolumeMesh& v) {
  double volume = 0;
  for (const auto& t : v.tets) {
    const Vec3 a = v.nodes()[t[0]], e1 = v.nodes()[t[1]] - a, e2 = v.nodes()[t[2]] - a, e3 = v.nodes()[t[3]] - a;
    volume += e1.dot(e2.cross(e3)) / 6;
  }
  return volume;
}

}  // namespace aniso
