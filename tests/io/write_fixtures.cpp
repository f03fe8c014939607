// io_write_fixtures OUTDIR: writes the hand-made test meshes (BoxFixture.h) in every
// format and variant, and OUTDIR/manifest.json with what each holds, for the tests that
// open them with the real clients (clients_test.py: Gmsh, meshio; ccx_tension_test.sh:
// CalculiX).
//   tet4, tet10   box 10 x 3 x 2, 4 x 2 x 2 cells, 6 Kuhn tetrahedra per cell
//   quad4, quad8  the same box's surface: quads on faces 1-5, triangles on face 6
//   parts         three such boxes side by side named "nut", "nut", "bolt"
//   open          quad4 without face 6's triangles: nodes on a face that has no element
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>

#include <nlohmann/json.hpp>

#include "io/MeshWriter.h"
#include "tests/io/BoxFixture.h"

using namespace aniso;
using namespace aniso::testing;
namespace fs = std::filesystem;

namespace {

struct Variant {
  const char* suffix;
  const char* ext;
  bool binary;
  int mshVersion;
};

const Variant kVariants[] = {{"", ".msh", false, 41}, {"_bin", ".msh", true, 41}, {"_22", ".msh", false, 22},
                             {"_22bin", ".msh", true, 22}, {"", ".inp", false, 41}, {"", ".vtu", false, 41},
                             {"_bin", ".vtu", true, 41}, {"", ".unv", false, 41}, {"", ".stl", false, 41},
                             {"_bin", ".stl", true, 41}, {"", ".obj", false, 41}, {"", ".off", false, 41}};

nlohmann::ordered_json describe(const Model& model, const SurfaceMesh& sm, const VolumeMesh* vm) {
  std::set<int> corners;
  for (const auto& t : sm.triangles) corners.insert(t.begin(), t.end());
  for (const auto& q : sm.quads) corners.insert(q.begin(), q.end());
  std::set<int> used = corners;  // nodes of any element
  for (const auto& m : sm.triangleMid) used.insert(m.begin(), m.end());
  for (const auto& m : sm.quadMid) used.insert(m.begin(), m.end());
  if (vm)
    for (const auto& t : vm->tets) used.insert(t.begin(), t.end());
  if (vm)
    for (const auto& m : vm->tetMid) used.insert(m.begin(), m.end());
  nlohmann::ordered_json j;
  j["nodes"] = sm.nodes.size();
  j["used_nodes"] = used.size();
  j["corner_nodes"] = corners.size();
  j["triangles"] = sm.triangles.size();
  j["quads"] = sm.quads.size();
  j["tets"] = vm ? vm->tets.size() : 0;
  j["quadratic"] = !sm.triangleMid.empty() || !sm.quadMid.empty();
  j["faces"] = model.faces.size();
  std::set<int> meshed(sm.triangleFace.begin(), sm.triangleFace.end());
  meshed.insert(sm.quadFace.begin(), sm.quadFace.end());
  j["face_groups"] = nlohmann::ordered_json::array();
  for (int f : meshed) j["face_groups"].push_back("FACE" + std::to_string(f + 1));
  j["solids"] = vm ? model.solids.size() : 0;
  return j;
}

template <class Mesh>
void writeAll(const std::string& name, const Model& model, const Mesh& mesh, const fs::path& out,
              nlohmann::ordered_json& manifest, nlohmann::ordered_json entry) {
  entry["files"] = nlohmann::ordered_json::array();
  for (const Variant& v : kVariants) {
    io::WriteOptions o;
    o.binary = v.binary;
    o.mshVersion = v.mshVersion;
    const std::string file = name + v.suffix + v.ext;
    if constexpr (std::is_same_v<Mesh, VolumeMesh>)
      io::writeVolumeMesh(model, mesh, (out / file).string(), o);
    else
      io::writeSurfaceMesh(model, mesh, (out / file).string(), o);
    entry["files"].push_back(file);
  }
  manifest[name] = entry;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::cerr << "usage: io_write_fixtures OUTDIR\n";
    return 2;
  }
  try {
    const fs::path out(argv[1]);
    fs::create_directories(out);
    const Vec3 size(10, 3, 2);
    const std::array<int, 3> cells{4, 2, 2};
    nlohmann::ordered_json manifest;
    const Model box = boxModel(size, "BOX");
    for (bool quadratic : {false, true}) {
      const VolumeMesh vm = boxTets(size, cells, quadratic);
      auto d = describe(box, vm.surface, &vm);
      d["quadratic"] = quadratic;
      d["solid_names"] = {"BOX"};
      writeAll(quadratic ? "tet10" : "tet4", box, vm, out, manifest, d);
      const SurfaceMesh sm = boxSurface(size, cells, quadratic);
      auto ds = describe(box, sm, nullptr);
      ds["solid_names"] = nlohmann::ordered_json::array();
      writeAll(quadratic ? "quad8" : "quad4", box, sm, out, manifest, ds);
    }
    SurfaceMesh open = boxSurface(size, cells, false);
    open.triangles.clear();
    open.triangleFace.clear();
    auto dopen = describe(box, open, nullptr);
    dopen["solid_names"] = nlohmann::ordered_json::array();
    writeAll("open", box, open, out, manifest, dopen);
    Model parts = boxModel(size, "nut");
    VolumeMesh partsMesh = boxTets(size, {2, 1, 1}, false);
    appendShifted(parts, partsMesh, boxModel(size, "nut"), boxTets(size, {2, 1, 1}, false), Vec3(0, 5, 0));
    appendShifted(parts, partsMesh, boxModel(size, "bolt"), boxTets(size, {2, 1, 1}, false), Vec3(0, 10, 0));
    auto dp = describe(parts, partsMesh.surface, &partsMesh);
    dp["solid_names"] = {"nut", "nut_2", "bolt"};
    writeAll("parts", parts, partsMesh, out, manifest, dp);
    std::ofstream(out / "manifest.json") << manifest.dump(1) << '\n';
    return 0;
  } catch (const std::exception& e) {
    std::cerr << "io_write_fixtures: " << e.what() << '\n';
    return 1;
  }
}
