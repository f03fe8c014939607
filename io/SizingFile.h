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
#include <optional>
#include <string>
#include <vector>

#include "mesher/core/Types.h"
#include "mesher/metric/Metric.h"

namespace aniso::io {

struct SizingSource {
  enum class Kind { Point, Segment, Box } kind = Kind::Point;
  Vec3 a = Vec3::Zero();  ///< point, segment start, box min
  Vec3 b = Vec3::Zero();  ///< segment end, box max
  double radius = 0;
  Metric3d metric;

  /// Is x inside the region of the source (ball, capsule, box)?
  bool contains(const Vec3& x) const;
};

struct SizingFile {
  std::optional<Metric3d> global;
  std::vector<SizingSource> sources;
};

/// Reads and checks a sizing file; throws InputError naming the file and the field.
SizingFile readSizingFile(const std::string& path);

}  // namespace aniso::io
