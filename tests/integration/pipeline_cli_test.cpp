// meshModel (mesher/pipeline/Pipeline.h) gives the mesh the CLI writes, byte for byte: the
// same model read and prepared by cad/, the CLI's defaults as a MeshRequest, both written by
// the same io writer. The models cover each stage of the pipeline: a plain 3D run, alg. 3.3's
// proximity round (periodic_u_cst at the defaults: one round kept), the coarse-solid retry
// (models/blocks2.step at the defaults: kept) and a surface run.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "cad/CadModel.h"
#include "io/MeshWriter.h"
#include "mesher/pipeline/Pipeline.h"

namespace aniso {
namespace {

namespace fs = std::filesystem;

/// Element budget given to both sides (the CLI's default depends on the machine's memory).
constexpr double kBudget = 1e8;

std::string readBytes(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

struct BothRuns {
  MeshResult result;
  bool sameAsCli = false;
};

/// Meshes `model` through the library and through the CLI (`dim`, defaults otherwise) and
/// compares the two .msh files.
BothRuns meshBoth(const std::string& path, int dim, bool thesisTable = false) {
  const fs::path dir = fs::temp_directory_path() / ("pipeline_cli_" + fs::path(path).stem().string() + "_" + std::to_string(dim));
  fs::create_directories(dir);
  const fs::path cliOut = dir / "cli.msh", libOut = dir / "lib.msh";
  const std::string cmd = std::string(ANISOMESH_CLI) + " mesh '" + path + "' -o '" + cliOut.string() + "' --dim " +
                          std::to_string(dim) + " --max-elements 1e8" +
                          (thesisTable ? " --hmax-rel 0.5 --curvature-ratio 0.15 --chord-deviation-rel 0" : "") + " > /dev/null 2>&1";
  EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;

  cad::CadModel cad = cad::CadModel::read(path);
  cad.prepare({});
  const Model model = cad.topology();
  MeshRequest request;
  if (thesisTable) request.options.sizing = SizingParameters{};  // the thesis' table 5.2 sizing
  request.options.dim = dim;
  request.options.maxElements = kBudget;
  request.options.sizing.anisotropy = 1;  // the CLI's default (MeshArgs::anisotropyGiven)
  BothRuns run{meshModel(model, request), false};
  EXPECT_TRUE(run.result.meshed());
  if (run.result.volumeRan) io::writeVolumeMesh(model, run.result.volume.mesh, libOut.string());
  else io::writeSurfaceMesh(model, run.result.surface.mesh, libOut.string());
  const std::string a = readBytes(cliOut), b = readBytes(libOut);
  run.sameAsCli = !a.empty() && a == b;
  fs::remove_all(dir);
  return run;
}

const std::string kModels = std::string(ANISOMESH_SHARED_DIR) + "/models/";
const std::string kOwn = std::string(ANISOMESH_SOURCE_DIR) + "/models/";

TEST(PipelineCli, VolumeOfBracketIsTheCliMesh) {
  const BothRuns r = meshBoth(kOwn + "bracket.step", 3);
  EXPECT_TRUE(r.sameAsCli);
  EXPECT_EQ(r.result.proximity.rounds, 0);
  EXPECT_FALSE(r.result.coarse.refinedKept);
  EXPECT_GT(r.result.volume.mesh.tets.size(), 0u);
}

TEST(PipelineCli, SurfaceOfBracketIsTheCliMesh) {
  const BothRuns r = meshBoth(kOwn + "bracket.step", 2);
  EXPECT_TRUE(r.sameAsCli);
  EXPECT_FALSE(r.result.volumeRan);
  EXPECT_GT(r.result.surface.mesh.triangles.size(), 0u);
}

TEST(PipelineCli, ProximityRoundIsTheCliMesh) {
  const BothRuns r = meshBoth(kModels + "periodic_u_cst.step", 3, true);
  EXPECT_TRUE(r.sameAsCli);
  EXPECT_EQ(r.result.proximity.rounds, 1);  // the round is the point of this case
  bool kept = false;
  for (const StageDecision& d : r.result.decisions) kept |= d.stage == "proximity" && d.decision.find("kept") != std::string::npos;
  EXPECT_TRUE(kept);
}

TEST(PipelineCli, CoarseSolidRetryIsTheCliMesh) {
  const BothRuns r = meshBoth(kOwn + "blocks2.step", 3, true);
  EXPECT_TRUE(r.sameAsCli);
  EXPECT_EQ(r.result.coarse.solids, 2);
  EXPECT_TRUE(r.result.coarse.refinedKept);
}

}  // namespace
}  // namespace aniso
