#pragma once
// Location of a refinement point seen from the triangle being refined (thesis sec. 4.5,
// CCS item 1: "the circumcenter may lie outside the original triangle, which requires
// searching for containing triangle with neighbor-traversing procedure starting from the
// original triangle (due to the constrained triangulation this localization procedure is
// not guaranteed to succeed)").
//
// A straight walk from the centroid o of `from` towards p with exact orient2d: in each
// triangle the edge crossed by the segment o→p is left through, until a triangle contains
// p (closed). The walk is Blocked when it would have to cross a constrained edge or the
// triangulation boundary — p is then outside the face or behind a contour as seen from
// `from` — or after maxSteps triangles. Unlike del2d::locate it never goes around an
// obstacle, so a Found point is visible from the refined triangle inside the face.
// Read-only; no allocation.
#include <cstddef>

#include "mesher/delaunay/Triangulation2d.h"

namespace aniso::face {

struct VisibleLocation {
  bool found = false;
  del2d::TriId tri;        ///< Found: a triangle whose closure contains p
  std::size_t steps = 0;
};

VisibleLocation locateVisible(const del2d::Triangulation2d& tri, del2d::TriId from, const Vec2& p,
                              std::size_t maxSteps);

}  // namespace aniso::face
