// Small polyhedron reconnection (improve/PolyhedronReconnection.h) on a film whose top and
// bottom are the same triangulation: the flat tets between two columns of nodes that no
// flip or edge removal takes away.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "mesher/volume/TetQuality.h"
#include "mesher/volume/VolumeMesher.h"
#include "mesher/volume/improve/PolyhedronReconnection.h"
#include "volume_refine_fixture.h"
#include "volume_test_models.h"

namespace aniso {
namespace {

using del3d::TetId;

// 16 x 16 cells, 15 times wider than the film is thick, top nodes 0.1 % of a cell off
// their bottom nodes
constexpr int kCells = 16;
constexpr double kThickness = 1.0 / kCells / 15;

VolumeMeshResult meshFilm(const voltest::SolidModel& m, bool improve) {
  VolumeMesherInput in;
  in.model = &m.model;
  in.surface = &m.surface;
  in.options.threads = 1;
  in.validate = true;
  in.improve = improve;
  return meshVolumes(in);
}

double counter(const SolidOutcome& o, const std::string& name) {
  for (const auto& [k, v] : o.counters)
    if (k == name) return v;
  return -1;
}

TEST(PolyhedronReconnection, AFilmMeshedAlikeOnBothSidesKeepsNoFlatTet) {
  const voltest::SolidModel m = voltest::columnFilm(kCells, kThickness, 0.3, 0.001);
  const VolumeMeshResult before = meshFilm(m, false);
  ASSERT_TRUE(before.ok());
  ASSERT_LT(before.quality.refereeMinDihedral, 0.1);  // the case: flat tets between columns
  const VolumeMeshResult r = meshFilm(m, true);
  ASSERT_TRUE(r.ok()) << voltest::joined(r.solids[0].problems.empty() ? std::vector<std::string>{}
                                                                      : std::vector<std::string>{r.solids[0].problems[0].detail});
  EXPECT_GT(counter(r.solids[0], "sliver_reconnections"), 0);
  EXPECT_GE(r.quality.refereeMinDihedral, 2.0);
  EXPECT_NEAR(r.quality.volume, m.volume, 1e-12);
}

TEST(PolyhedronReconnection, ReplacesAFlatTetBetweenTwoColumnsByAValidTetrahedralization) {
  // the film's tets before improvement, as a SolidTetMesh: its flattest tet reconnected
  const voltest::SolidModel m = voltest::columnFilm(kCells, kThickness, 0.3, 0.001);
  const VolumeMeshResult r = meshFilm(m, false);
  ASSERT_TRUE(r.ok());
  std::set<testing::Triple> boundary;
  std::vector<std::array<int, 4>> tets(r.mesh.tets.begin(), r.mesh.tets.end());
  SolidTetMesh s = testing::solidFrom(r.mesh.nodes(), tets, boundary);
  const auto dihedral = [&](TetId t) {
    const std::uint32_t* v = s.mesh.tetVertices(t);
    return tetMinDihedral(s.mesh.point(del3d::VertexId(v[0])), s.mesh.point(del3d::VertexId(v[1])),
                          s.mesh.point(del3d::VertexId(v[2])), s.mesh.point(del3d::VertexId(v[3])));
  };
  // the flattest tet (between two columns), replaced with its surroundings by tets whose
  // smallest dihedral angle is larger
  TetId flattest;
  for (std::uint32_t k = 0; k < s.mesh.tetSlots(); ++k)
    if (s.mesh.isAlive(TetId(k)) && (!flattest.valid() || dihedral(TetId(k)) < dihedral(flattest))) flattest = TetId(k);
  const double before = dihedral(flattest);
  ASSERT_LT(before, 0.1);
  const std::size_t tetsBefore = s.mesh.numTets();
  std::vector<TetId> created;
  ASSERT_TRUE(improve3d::reconnectPolyhedron(s, flattest, created));
  EXPECT_FALSE(s.mesh.isAlive(flattest));
  EXPECT_LE(s.mesh.numTets(), tetsBefore);
  for (const TetId t : created) EXPECT_GT(dihedral(t), before);
  const std::vector<std::string> problems = testing::checkSolid(s, boundary);
  EXPECT_TRUE(problems.empty()) << voltest::joined(problems);
  EXPECT_NEAR(testing::meshVolume(s.mesh), m.volume, 1e-12);
}

}  // namespace
}  // namespace aniso
