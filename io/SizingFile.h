#pragma once
// The user's sizing file (--sizing FILE.json): a global size or metric and a list of
// extended metric sources (thesis sec. 3.2.2, fig. 3.3), in model coordinates:
//
//   {"global": {"h": 2.0}                                  // isotropic, or
//    "global": {"h": [h1, h2, h3], "directions": [[...], [...], [...]]},
//    "sources": [
//      {"type": "point",   "at": [x, y, z], "radius": r, "h": 0.5},
//      {"type": "segment", "from": [x, y, z], "to": [x, y, z], "radius": r,
//       "h": [0.1, 1, 1], "directions": [[1, 0, 0], [0, 1, 0], [0, 0, 1]]},
//      {"type": "box",     "min": [x, y, z], "max": [x, y, z], "h": 0.3}]}
//
// "h" is one length (isotropic) or three lengths along "directions" (orthonormal; default
// the coordinate axes). "radius" (≥ 0, default 0) widens a point or segment source into a
// ball or capsule. Inside a source's region the mesh metric is intersected with the
// source's metric (it can only make elements smaller).
#include <string>

#include "mesher/sizing/UserSizing.h"

namespace aniso::io {

/// Reads and checks a sizing file; throws InputError naming the file and the field.
UserSizing readSizingFile(const std::string& path);

}  // namespace aniso::io
