// The grading of a volume mesh (mesher/pipeline/MeshGrade.h) and the curved volume it
// compares with the CAD's (mesher/highorder/CurvedVolume.h), on models/cylinder.step
// (r 10, h 40: 12566.37) at the program's coarse defaults (12 segments per circle).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "cad/CadModel.h"
#include "mesher/highorder/CurvedVolume.h"
#include "mesher/pipeline/MeshGrade.h"
#include "mesher/pipeline/Pipeline.h"

namespace aniso {
namespace {

const double kCylinderVolume = std::numbers::pi * 10 * 10 * 40;

struct Meshed {
  Model model;
  MeshResult result;
};

Meshed meshCylinder() {
  cad::CadModel cad = cad::CadModel::read(std::string(ANISOMESH_SOURCE_DIR) + "/models/cylinder.step");
  cad.prepare({});
  Meshed m{cad.topology(), {}};
  MeshRequest request;
  request.options.dim = 3;
  request.options.sizing.anisotropy = 1;
  request.options.sizing.chordDeviationRel = 0;  // 12 per circle alone: the polygon's deficit
  request.options.maxElements = 1e8;
  m.result = meshModel(m.model, request);
  return m;
}

TEST(MeshGrade, CurvedVolumeRemovesTheChordalDeficit) {
  const Meshed m = meshCylinder();
  ASSERT_TRUE(m.result.meshed());
  ASSERT_EQ(m.model.solids.size(), 1u);
  EXPECT_NEAR(m.model.solids[0].cadVolume, kCylinderVolume, 1e-6 * kCylinderVolume);
  const double straight = m.result.volume.solids.at(0).volume;
  EXPECT_LT(straight, 0.985 * kCylinderVolume);  // the coarse polygon loses more than the bar
  const std::vector<double> curved = curvedSolidVolumes(m.model, m.result.volume.mesh);
  EXPECT_NEAR(curved.at(0), kCylinderVolume, 2e-3 * kCylinderVolume);
  for (const Problem& p : m.result.problems) EXPECT_NE(p.code, "volume-mismatch") << p.detail;
}

TEST(MeshGrade, NamesTheSolidWhoseVolumeDiffersFromTheCad) {
  Meshed m = meshCylinder();
  ASSERT_TRUE(m.result.meshed());
  m.model.solids[0].cadVolume *= 1.05;  // a CAD that states 5 % more than it bounds
  const std::vector<Problem> problems = gradeVolumeMesh(m.model, m.result.volume, true);
  int found = 0;
  for (const Problem& p : problems)
    if (p.code == "volume-mismatch") {
      ++found;
      EXPECT_EQ(p.entity.kind, EntityKind::Solid);
      EXPECT_EQ(p.entity.id, 1);
      EXPECT_EQ(p.severity, Severity::Degraded);
    }
  EXPECT_EQ(found, 1);
}

TEST(MeshGrade, SliversAndLowQualityAreDegraded) {
  Meshed m = meshCylinder();
  ASSERT_TRUE(m.result.meshed());
  VolumeMeshResult v = m.result.volume;
  v.solids.at(0).quality.refereeMinDihedral = 1.0;
  QualityStats poor;
  poor.add(0.5);
  v.quality.meanRatio = poor;
  std::vector<std::string> codes;
  for (const Problem& p : gradeVolumeMesh(m.model, v, true)) {
    codes.push_back(p.code);
    if (p.code == "slivers") {  // where the flattest tet is, and the CAD faces at its nodes
      EXPECT_NE(p.detail.find("the flattest at ("), std::string::npos) << p.detail;
      EXPECT_EQ(p.entity.id, 1);
    }
  }
  EXPECT_EQ(codes, (std::vector<std::string>{"slivers", "low-quality"}));
  codes.clear();
  for (const Problem& p : gradeVolumeMesh(m.model, v, false)) codes.push_back(p.code);  // anisotropic
  EXPECT_EQ(codes, (std::vector<std::string>{"slivers"}));
}

TEST(MeshGrade, LowQualityNamesTheSolidsThatPullTheMeanDown) {
  Meshed m = meshCylinder();
  ASSERT_TRUE(m.result.meshed());
  VolumeMeshResult v = m.result.volume;
  QualityStats poor;
  for (int i = 0; i < 4; ++i) poor.add(0.25);
  v.solids.at(0).quality.meanRatio = poor;
  v.quality.meanRatio = poor;
  std::string detail;
  for (const Problem& p : gradeVolumeMesh(m.model, v, true))
    if (p.code == "low-quality") detail = p.detail;
  // 2 V / A of the cylinder: 2 * 12566 / (2 pi 10 40 + 2 pi 100) = 8
  EXPECT_NE(detail.find("mostly solid 1 '"), std::string::npos) << detail;
  EXPECT_NE(detail.find("(4 tets, mean 0.25, about 8 thick)"), std::string::npos) << detail;
}

}  // namespace
}  // namespace aniso
