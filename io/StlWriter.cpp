// STL writer, ASCII or binary: the triangles of the surface mesh, quads split in two along
// their (0, 2) diagonal, facet normals from the corners. Written here rather than through
// OpenMesh: OpenMesh's ASCII STL puts a blank line in every facet, which readers that parse
// the format line by line (meshio 5) reject.
#include <Eigen/Geometry>
#include <bit>
#include <cstdint>
#include <cstdio>
#include <ostream>
#include <vector>

#include "io/AtomicFile.h"
#include "io/FormatWriters.h"
#include "mesher/core/Error.h"

namespace aniso::io {

static_assert(std::endian::native == std::endian::little, "binary STL is little-endian");

void writeStl(const OutputMesh& m, const std::string& path, const WriteOptions& opt) {
  const SurfaceMesh& sm = m.surface;
  std::vector<std::array<int, 3>> tris = sm.triangles;
  for (const auto& q : sm.quads) {
    tris.push_back({q[0], q[1], q[2]});
    tris.push_back({q[0], q[2], q[3]});
  }
  if (opt.binary && tris.size() > 0xffffffffu) throw MeshingError(path + ": too many triangles for binary STL");
  AtomicFile file(path, opt.binary);
  std::ostream& o = file.stream();
  auto normal = [&](const std::array<int, 3>& t) {
    const Vec3 n = (sm.nodes[t[1]] - sm.nodes[t[0]]).cross(sm.nodes[t[2]] - sm.nodes[t[0]]);
    const double l = n.norm();
    return l > 0 ? Vec3(n / l) : Vec3::Zero();
  };
  if (opt.binary) {
    char header[80] = "anisomesh";
    o.write(header, sizeof header);
    const auto count = static_cast<std::uint32_t>(tris.size());
    o.write(reinterpret_cast<const char*>(&count), sizeof count);
    for (const auto& t : tris) {
      float v[12];
      const Vec3 n = normal(t);
      for (int k = 0; k < 3; ++k) v[k] = static_cast<float>(n[k]);
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) v[3 + 3 * c + k] = static_cast<float>(sm.nodes[t[c]][k]);
      o.write(reinterpret_cast<const char*>(v), sizeof v);
      const std::uint16_t attributes = 0;
      o.write(reinterpret_cast<const char*>(&attributes), sizeof attributes);
    }
  } else {
    char buf[160];
    o << "solid anisomesh\n";
    for (const auto& t : tris) {
      const Vec3 n = normal(t);
      std::snprintf(buf, sizeof buf, "  facet normal %.9g %.9g %.9g\n    outer loop\n", n.x(), n.y(), n.z());
      o << buf;
      for (int c : t) {
        std::snprintf(buf, sizeof buf, "      vertex %.17g %.17g %.17g\n", sm.nodes[c].x(), sm.nodes[c].y(), sm.nodes[c].z());
        o << buf;
      }
      o << "    endloop\n  endfacet\n";
    }
    o << "endsolid anisomesh\n";
  }
  file.commit();
}

}  // namespace aniso::io
