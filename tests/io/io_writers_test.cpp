// The writers on hand-made meshes: group names, the INP surfaces on the right CAD faces,
// byte-identical output, atomic failure. (The real clients read the files in
// tests/io/clients_test.py and ccx_tension_test.sh.)
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "io/ElementOrder.h"
#include "io/MeshWriter.h"
#include "io/OutputMesh.h"
#include "io/readers/ReadMesh.h"
#include "mesher/core/Error.h"
#include "tests/io/BoxFixture.h"

using namespace aniso;
using namespace aniso::io;
namespace fs = std::filesystem;
namespace fx = aniso::testing;

namespace {

/// A folder of this test's own, removed with everything in it when the test ends.
struct TempDir {
  fs::path path = fs::temp_directory_path() / ("aniso_io_test_" + std::to_string(::getpid()) + "_" +
                                               ::testing::UnitTest::GetInstance()->current_test_info()->name());
  TempDir() { fs::create_directories(path); }
  ~TempDir() { fs::remove_all(path); }
};

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

Model namedSolids(const std::vector<std::string>& names) {
  Model m;
  for (const auto& n : names) m.solids.push_back({n, -1, {}});
  return m;
}

}  // namespace

TEST(IoWriters, SolidNamesAreMadeUnique) {
  const auto n = groupNames(namedSolids({"nut", "bolt", "nut", "", "nut_2", "nut"})).solids;
  const std::vector<std::string> want = {"nut", "bolt", "nut_2", "SOLID4", "nut_2_2", "nut_3"};
  EXPECT_EQ(n, want);
}

TEST(IoWriters, As1AssemblyGetsEighteenDistinctNames) {
  // the part names of ../shared/models/as1-tu-203.stp in solid order (anisomesh info)
  const std::vector<std::string> parts = {"nut", "nut", "rod", "bolt", "nut", "bolt", "nut", "bolt", "nut",
                                          "l-bracket", "plate", "bolt", "nut", "bolt", "nut", "bolt", "nut", "l-bracket"};
  const auto names = groupNames(namedSolids(parts)).solids;
  EXPECT_EQ(std::set<std::string>(names.begin(), names.end()).size(), 18u);
  EXPECT_EQ(names[0], "nut");
  EXPECT_EQ(names[1], "nut_2");
  EXPECT_EQ(names[16], "nut_8");  // the eighth nut
  EXPECT_EQ(names[9], "l_bracket");  // the same name in every format (MSH had l-bracket)
  EXPECT_EQ(names[17], "l_bracket_2");
}

TEST(IoWriters, AbaqusNamesAreIdentifiersAvoidingOurSets) {
  const auto n = groupNames(namedSolids({"my part", "2x", "EALL", "face3", "Nut", "nut", "S_FACE12", "FACEPLATE", "Edge7"})).solids;
  const std::vector<std::string> want = {"my_part", "P_2x", "EALL_2", "face3_2", "Nut", "nut_2", "S_FACE12_2", "FACEPLATE", "Edge7_2"};
  EXPECT_EQ(n, want);
}

TEST(IoWriters, NamedFacesShareOneGroupNamedLikeTheParts) {
  Model m = namedSolids({"box"});
  for (const char* name : {"top", "", "load face", "top", "BOX", "FACE2"}) {
    m.faces.emplace_back();
    m.faces.back().name = name;
  }
  const GroupNames g = groupNames(m);
  ASSERT_EQ(g.faces.size(), 4u);
  EXPECT_EQ(g.faces[0].name, "top");
  EXPECT_EQ(g.faces[0].faces, (std::vector<int>{0, 3}));
  EXPECT_EQ(g.faces[1].name, "load_face");
  EXPECT_EQ(g.faces[1].faces, (std::vector<int>{2}));
  EXPECT_EQ(g.faces[2].name, "BOX_2");  // the part keeps its name
  EXPECT_EQ(g.faces[3].name, "FACE2_2");  // never one of the FACE<n> sets
  EXPECT_EQ(groupNames(namedSolids({"box"})).faces.size(), 0u);
}

TEST(IoWriters, InpSurfacesLieOnTheirCadFaces) {
  const Vec3 size(4, 2, 3);
  for (bool quadratic : {false, true}) {
    const Model model = fx::boxModel(size, "BOX");
    const VolumeMesh vm = fx::boxTets(size, {2, 2, 2}, quadratic);
    const TempDir dir;
    const fs::path file = dir.path / "box.inp";
    writeVolumeMesh(model, vm, file.string());
    // Parse the elements and the surfaces back.
    std::ifstream in(file);
    std::map<long long, std::vector<long long>> elements;
    std::map<int, std::vector<std::pair<long long, int>>> surfaces;
    std::string line, section;
    int face = 0;
    while (std::getline(in, line)) {
      if (line.rfind("**", 0) == 0) continue;
      if (line[0] == '*') {
        section = line.substr(0, line.find(','));
        if (section == "*SURFACE") face = std::stoi(line.substr(line.find("S_FACE") + 6));
        continue;
      }
      std::replace(line.begin(), line.end(), ',', ' ');
      std::istringstream s(line);
      if (section == "*ELEMENT") {
        long long id, n;
        s >> id;
        while (s >> n) elements[id].push_back(n);
      } else if (section == "*SURFACE") {
        long long id;
        std::string sk;
        s >> id >> sk;
        surfaces[face].push_back({id, std::stoi(sk.substr(1))});
      }
    }
    ASSERT_EQ(elements.size(), vm.tets.size());
    ASSERT_EQ(surfaces.size(), 6u);
    const double sides[6] = {0, size.x(), 0, size.y(), 0, size.z()};
    for (const auto& [f, entries] : surfaces) {
      const int axis = (f - 1) / 2;
      EXPECT_EQ(entries.size(), 8u) << "FACE" << f;  // 2x2 cells, 2 triangles each
      for (const auto& [id, k] : entries) {
        const auto& e = elements.at(id);
        ASSERT_EQ(e.size(), quadratic ? 10u : 4u);
        const int* corners = order::kAbaqusTetFaces[k - 1];
        for (int j = 0; j < 3; ++j)
          EXPECT_DOUBLE_EQ(vm.nodes()[e[corners[j]] - 1][axis], sides[f - 1]) << "FACE" << f << " element " << id << " S" << k;
      }
    }
  }
}

TEST(IoWriters, OutputIsByteIdentical) {
  const Vec3 size(1, 1, 1);
  const Model model = fx::boxModel(size, "BOX");
  const VolumeMesh vm = fx::boxTets(size, {2, 1, 1}, true);
  const TempDir dir;
  const fs::path& d = dir.path;
  for (const char* name : {"a.msh", "a.inp", "a.vtu", "a.unv"})
    for (bool binary : {false, true}) {
      WriteOptions o;
      o.binary = binary;
      writeVolumeMesh(model, vm, (d / name).string(), o);
      const std::string first = slurp(d / name);
      writeVolumeMesh(model, vm, (d / name).string(), o);
      EXPECT_EQ(first, slurp(d / name)) << name;
      EXPECT_FALSE(first.empty());
    }
}

TEST(IoWriters, FailuresLeaveNoFile) {
  const Vec3 size(1, 1, 1);
  const Model model = fx::boxModel(size, "BOX");
  VolumeMesh vm = fx::boxTets(size, {1, 1, 1}, false);
  const TempDir dir;
  const fs::path& d = dir.path;
  EXPECT_THROW(writeVolumeMesh(model, vm, (d / "a.xyz").string()), InputError);
  WriteOptions o;
  o.mshVersion = 30;
  EXPECT_THROW(writeVolumeMesh(model, vm, (d / "a.msh").string(), o), InputError);
  EXPECT_THROW(writeVolumeMesh(model, vm, (d / "no" / "c.msh").string()), InputError);  // no such folder
  vm.tets[0][2] = 10000;  // a node out of range
  EXPECT_THROW(writeVolumeMesh(model, vm, (d / "b.inp").string()), MeshingError);
  EXPECT_TRUE(fs::is_empty(d));
}

TEST(IoWriters, NodeDataIsReadBackFromEveryEncoding) {
  const Vec3 size(1, 1, 1);
  const Model model = fx::boxModel(size, "BOX");
  const VolumeMesh vm = fx::boxTets(size, {2, 1, 1}, true);
  // a function of the position: the readers may order the nodes otherwise (MSH 4.1 by entity)
  const auto u = [](const std::vector<Vec3>& nodes) {
    std::vector<double> v;
    for (const Vec3& p : nodes) v.insert(v.end(), {p.x() + 0.1, 2 * p.y(), -p.z() / 3});
    return v;
  };
  const NodeData d{"u", 3, u(vm.surface.nodes)};
  const TempDir dir;
  for (const char* name : {"a.msh", "a.vtu"})
    for (int version : {41, 22})
      for (bool binary : {false, true}) {
        WriteOptions o;
        o.binary = binary;
        o.mshVersion = version;
        o.nodeData = {d};
        const std::string path = (dir.path / name).string();
        writeVolumeMesh(model, vm, path, o);
        const ReadMesh back = readMesh(path);
        ASSERT_EQ(back.pointData.size(), 1u) << name << " " << version << " " << binary;
        EXPECT_EQ(back.pointData[0].name, "u");
        EXPECT_EQ(back.pointData[0].components, 3);
        EXPECT_EQ(back.pointData[0].values, u(back.nodes)) << name << " " << version << " " << binary;
      }
  WriteOptions o;
  o.nodeData = {d};
  EXPECT_THROW(writeVolumeMesh(model, vm, (dir.path / "a.inp").string(), o), InputError);
  o.nodeData[0].values.pop_back();
  EXPECT_THROW(writeVolumeMesh(model, vm, (dir.path / "b.msh").string(), o), MeshingError);
  EXPECT_FALSE(fs::exists(dir.path / "a.inp"));
  EXPECT_FALSE(fs::exists(dir.path / "b.msh"));
}

TEST(IoWriters, QualityOfRegularElements) {
  const Vec3 size(1, 1, 1);
  const Model model = fx::boxModel(size, "BOX");
  const SurfaceMesh sm = fx::boxSurface(size, {1, 1, 1}, false);
  const OutputMesh m(model, sm);
  ASSERT_GT(m.count(Shape::Quad), 0);
  for (int q = 0; q < m.count(Shape::Quad); ++q) EXPECT_NEAR(elementQuality(m, Shape::Quad, q), 1.0, 1e-12);
  // a right isosceles triangle: 4√3·(1/2) / (1 + 1 + 2)
  EXPECT_NEAR(elementQuality(m, Shape::Triangle, 0), std::sqrt(3.0) / 2, 1e-12);
}
