// anisomesh — command-line program. Parses options with CLI11, runs a subcommand, and turns
// every error into one line on stderr and an exit code: 0 ok, 2 bad input, 3 meshing failure.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <map>
#include <memory>

#include "mesher/core/Error.h"
#include "tools/cli/AdaptCommand.h"
#include "tools/cli/Commands.h"
#include "tools/cli/TerminalSink.h"

using namespace aniso;

namespace {

void addOverlapsOption(CLI::App& cmd, cad::OverlapPolicy& p) {
  cmd.add_option("--overlaps", p,
                 "Overlapping solids: merge (each common region meshed once, in the smaller part), keep (left "
                 "unfragmented, overlapping meshes) or error (exit 2)")
      ->transform(CLI::CheckedTransformer(std::map<std::string, cad::OverlapPolicy>{
          {"merge", cad::OverlapPolicy::Merge}, {"keep", cad::OverlapPolicy::Keep}, {"error", cad::OverlapPolicy::Error}}))
      ->default_str("merge");
}

void addSizingOptions(CLI::App& cmd, SizingParameters& s) {
  cmd.add_option("--size", s.size, "Uniform target element size H (model units)");
  cmd.add_option("--hmax", s.hmax, "Largest element size (model units)");
  cmd.add_option("--hmin", s.hmin, "Smallest element size (model units)");
  cmd.add_option("--hmax-rel", s.hmaxRel, "Largest size relative to the model diagonal (γ_hmax)")->capture_default_str();
  cmd.add_option("--hmin-rel", s.hminRel, "Smallest size relative to the model diagonal (γ_hmin)")->capture_default_str();
  cmd.add_option("--curvature-ratio", s.curvatureRatio, "Edge length / curvature radius (γ_c)")->capture_default_str();
  cmd.add_option("--gradation", s.gradation, "Metric gradation ratio (γ_M)")->capture_default_str();
  cmd.add_option("--anisotropy", s.anisotropy, "Largest element stretch ratio (γ_a); 1 = isotropic")->capture_default_str();
  cmd.add_option("--contour-anisotropy", s.contourAnisotropy, "Stretch ratio along curved contours (γ_ac)")->capture_default_str();
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"anisomesh: anisotropic triangle, quad and tetrahedral meshes of CAD models"};
  app.set_version_flag("--version", std::string("anisomesh ") + ANISOMESH_VERSION);
  app.require_subcommand(1, 1);
  int verbose = 0;
  bool quiet = false;
  app.add_flag("-v,--verbose", verbose, "More messages on stderr");
  app.add_flag("-q,--quiet", quiet, "Only errors on stderr");
  bool progressLines = false;
  app.add_flag("--progress", progressLines,
               "Progress as lines on stderr even when it is not a terminal (for programs running anisomesh)");

  cli::InfoArgs info;
  CLI::App* infoCmd = app.add_subcommand("info", "Describe a CAD model: counts, volume, area, solids");
  infoCmd->add_option("FILE", info.file, "STEP, IGES or BREP file")->required();
  infoCmd->add_flag("--json", info.json, "One JSON object on stdout");
  infoCmd->add_flag("--faces", info.faces, "Also list every face and edge: id, type, area or length, centroid, solids, part");
  infoCmd->add_flag("!--no-fragment", info.fragment, "Do not fragment touching solids in the prepared model");
  addOverlapsOption(*infoCmd, info.overlaps);
  infoCmd->fallthrough();

  cli::MeshArgs mesh;
  CLI::App* meshCmd = app.add_subcommand("mesh", "Mesh a CAD model or a .json analytic model");
  meshCmd->add_option("FILE", mesh.file, "STEP, IGES, BREP or .json analytic model")->required();
  meshCmd->add_option("-o,--output", mesh.output, "Output mesh: .msh .inp .vtu .stl .obj .off .unv")->required();
  meshCmd->add_option("--dim", mesh.options.dim, "2: surface mesh, 3: volume mesh (default 3 if the model has solids)")
      ->check(CLI::IsMember({2, 3}));
  meshCmd->add_option("--order", mesh.options.order, "Element order")->check(CLI::IsMember({1, 2}))->capture_default_str();
  meshCmd->add_flag("--quad", mesh.options.quad, "Quad-dominant surface mesh");
  meshCmd->add_option("--quad-method", mesh.options.quadMethod, "--quad conversion: merge, morph or mixed (thesis 4.7)")
      ->transform(CLI::CheckedTransformer(std::map<std::string, QuadMethod>{
          {"merge", QuadMethod::Merge}, {"morph", QuadMethod::Morph}, {"mixed", QuadMethod::Mixed}}))
      ->capture_default_str();
  addSizingOptions(*meshCmd, mesh.options.sizing);
  meshCmd->add_option("--sizing", mesh.options.sizingFile, "User sizing sources (JSON)");
  meshCmd->add_option("--threads", mesh.options.threads, "Threads (0 = all cores)")->check(CLI::Range(0, 4096))->capture_default_str();
  meshCmd->add_option("--max-elements", mesh.options.maxElements,
                      "Element budget (triangles, plus tets in 3D) checked before meshing; over it the finest sizes are "
                      "coarsened, or the run stops (exit 2). Default: the available memory / bytes per element")
      ->check(CLI::PositiveNumber);
  meshCmd->add_option("--time-limit", mesh.timeLimit, "Stop after S seconds: status failed, exit 3, no mesh (0 = none)")
      ->check(CLI::NonNegativeNumber);
  meshCmd->add_flag("--binary", mesh.binary, "Binary output where the format has it");
  meshCmd->add_option("--msh-version", mesh.mshVersion, "MSH format version: 4.1 or 2.2")
      ->transform(CLI::CheckedTransformer(std::map<std::string, int>{{"4.1", 41}, {"2.2", 22}}))
      ->default_str("4.1");
  meshCmd->add_flag("!--no-fragment", mesh.fragment, "Do not make touching solids conformal");
  addOverlapsOption(*meshCmd, mesh.overlaps);
  meshCmd->add_option("--report", mesh.report, "Write the JSON run report here");
  meshCmd->fallthrough();

  cli::SizingArgs sizing;
  CLI::App* sizingCmd = app.add_subcommand("sizing", "Write the initial control space (the metric field) as VTU");
  sizingCmd->add_option("FILE", sizing.file, "STEP, IGES, BREP or .json analytic model")->required();
  sizingCmd->add_option("-o,--output", sizing.output, "Output .vtu file")->required();
  sizingCmd->add_option("--face", sizing.face, "Only this face (1-based), in its parametric plane")->check(CLI::PositiveNumber);
  addSizingOptions(*sizingCmd, sizing.params);
  sizingCmd->add_option("--sizing", sizing.sizingFile, "User sizing sources (JSON)");
  sizingCmd->add_flag("!--no-fragment", sizing.fragment, "Do not make touching solids conformal");
  sizingCmd->fallthrough();

  cli::CheckArgs check;
  CLI::App* checkCmd = app.add_subcommand("check", "Check a mesh file: counts, closed/manifold/oriented, inverted elements, quality");
  checkCmd->add_option("MESH", check.file, "MSH, INP, VTU, STL, OBJ or OFF file")->required();
  checkCmd->add_flag("--json", check.json, "One JSON object on stdout");
  checkCmd->fallthrough();

  cli::AdaptArgs adapt;
  CLI::App* adaptCmd = cli::addAdaptCommand(app, adapt);
  addSizingOptions(*adaptCmd, adapt.mesh.options.sizing);

  // CLI11 reports an unknown command as a missing one: name it instead.
  if (argc > 1 && argv[1][0] != '-' &&
      app.get_subcommands([&](CLI::App* sub) { return sub->get_name() == argv[1]; }).empty()) {
    std::fprintf(stderr, "anisomesh: unknown command '%s' (see anisomesh --help)\n", argv[1]);
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    std::fprintf(stderr, "anisomesh: %s (see anisomesh --help)\n", e.what());
    return 2;
  }
  setLogSink(std::make_shared<cli::TerminalSink>(quiet ? -1 : verbose, progressLines));

  try {
    if (infoCmd->parsed()) return cli::runInfo(info);
    if (meshCmd->parsed()) {
      mesh.anisotropyGiven = meshCmd->count("--anisotropy") > 0;
      return cli::runMesh(mesh);
    }
    if (sizingCmd->parsed()) return cli::runSizing(sizing);
    if (checkCmd->parsed()) return cli::runCheck(check);
    if (adaptCmd->parsed()) return cli::runAdapt(adapt);
  } catch (const InputError& e) {
    std::fprintf(stderr, "anisomesh: %s\n", e.what());
    return 2;
  } catch (const MeshingError& e) {
    std::fprintf(stderr, "anisomesh: meshing failed: %s\n", e.what());
    return 3;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "anisomesh: out of memory\n");
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "anisomesh: internal error: %s\n", e.what());
    return 3;
  }
  return 2;
}
