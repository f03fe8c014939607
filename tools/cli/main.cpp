// anisomesh — command-line program. Parses options with CLI11, runs a subcommand, and turns
// every error into one line on stderr and an exit code: 0 ok, 2 bad input, 3 meshing failure.
#include <CLI/CLI.hpp>

#include <cstdio>
#include <exception>
#include <map>
#include <memory>

#include "mesher/core/Error.h"
#include "tools/cli/AdaptCommand.h"
#include "tools/cli/ChoiceOption.h"
#include "tools/cli/Commands.h"
#include "tools/cli/HelpFormat.h"
#include "tools/cli/SizeOptions.h"
#include "tools/cli/TerminalSink.h"

using namespace aniso;

namespace {

constexpr const char* kOutput = "Output";
constexpr const char* kModel = "Model preparation";
constexpr const char* kPerformance = "Time, memory and threads";
constexpr const char* kMessages = "Messages";

void addOverlapsOption(CLI::App& cmd, cad::OverlapPolicy& p) {
  cmd.add_option("--overlaps", p,
                 "Overlapping solids: merge (each common region meshed once, in the smaller part; a thin film where it leaves no narrow faces), keep (left "
                 "unfragmented, overlapping meshes) or error (exit 2)")
      ->transform(cli::choice(std::vector<std::pair<std::string, cad::OverlapPolicy>>{
          {"merge", cad::OverlapPolicy::Merge}, {"keep", cad::OverlapPolicy::Keep}, {"error", cad::OverlapPolicy::Error}}))
      ->option_text("merge|keep|error")
      ->default_str("merge")
      ->group(kModel);
}

/// -v, -q and --progress on the program and on every command (so that each command's help
/// lists them and they may come before or after the command).
struct MessageFlags {
  int verbose = 0;
  bool quiet = false;
  bool progress = false;
  void add(CLI::App& cmd) {
    cmd.add_flag("-v,--verbose", verbose, "More messages on stderr")->group(kMessages);
    cmd.add_flag("-q,--quiet", quiet, "Only errors on stderr")->group(kMessages);
    cmd.add_flag("--progress", progress,
                 "Progress as lines on stderr even when it is not a terminal (for programs running anisomesh)")
        ->group(kMessages);
  }
};

constexpr const char* kUnits =
    "Lengths are in model units: millimetres for STEP and IGES (the reader converts the file's unit), the "
    "file's own unit for BREP and .json models.";

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"anisomesh: triangle, quad and tetrahedral meshes of CAD models (STEP, IGES, BREP)"};
  app.formatter(std::make_shared<cli::PeopleFormatter>());
  app.set_version_flag("--version", std::string("anisomesh ") + ANISOMESH_VERSION);
  app.require_subcommand(1, 1);
  app.footer("Example: anisomesh mesh part.step -o part.inp\n" + std::string(kUnits) +
             "\nExit codes: 0 ok, 2 bad input or options, 3 meshing failed. Help on a command: anisomesh COMMAND --help");
  MessageFlags messages;
  messages.add(app);

  cli::InfoArgs info;
  CLI::App* infoCmd = app.add_subcommand("info", "Describe a CAD model: counts, volume, area, solids");
  infoCmd->add_option("FILE", info.file, "STEP, IGES or BREP file")->required();
  infoCmd->add_flag("--json", info.json, "One JSON object on stdout")->group(kOutput);
  infoCmd->add_flag("--faces", info.faces, "Also list every face and edge: id, type, area or length, centroid, solids, part")
      ->group(kOutput);
  infoCmd->add_flag("!--no-fragment", info.fragment, "Do not fragment touching solids in the prepared model")->group(kModel);
  addOverlapsOption(*infoCmd, info.overlaps);
  messages.add(*infoCmd);
  infoCmd->fallthrough();

  cli::MeshArgs mesh;
  mesh.options.sizing = SizingParameters::forAnalysis();
  CLI::App* meshCmd = app.add_subcommand("mesh", "Mesh a CAD model or a .json analytic model");
  meshCmd->footer(kUnits);
  meshCmd->add_option("FILE", mesh.file, "STEP, IGES, BREP or .json analytic model")->required();
  meshCmd->add_option("-o,--output", mesh.output, "Output mesh, format by extension: .msh .inp .vtu .stl .obj .off .unv")
      ->option_text("FILE")
      ->required()
      ->group(kOutput);
  meshCmd->add_option("--dim", mesh.options.dim, "2: surface mesh, 3: volume mesh (default 3 if the model has solids)")
      ->check(CLI::IsMember({2, 3}))
      ->option_text("2|3")
      ->group(kOutput);
  meshCmd->add_option("--order", mesh.options.order, "Element order: 1 linear, 2 quadratic (mid-edge nodes on the CAD)")
      ->check(CLI::IsMember({1, 2}))
      ->option_text("1|2")
      ->default_str("1")
      ->group(kOutput);
  meshCmd->add_flag("--quad", mesh.options.quad, "Quad-dominant surface mesh")->group(kOutput);
  meshCmd->add_option("--quad-method", mesh.options.quadMethod, "How --quad makes quads from triangles (thesis 4.7)")
      ->transform(cli::choice(std::vector<std::pair<std::string, QuadMethod>>{
          {"merge", QuadMethod::Merge}, {"morph", QuadMethod::Morph}, {"mixed", QuadMethod::Mixed}}))
      ->option_text("merge|morph|mixed")
      ->default_str("merge")
      ->group(kOutput);
  meshCmd->add_flag("--binary", mesh.binary, "Binary output where the format has it")->group(kOutput);
  meshCmd->add_option("--msh-version", mesh.mshVersion, "MSH format version")
      ->transform(cli::choice(std::vector<std::pair<std::string, int>>{{"4.1", 41}, {"2.2", 22}}))
      ->option_text("4.1|2.2")
      ->default_str("4.1")
      ->group(kOutput);
  meshCmd->add_option("--report", mesh.report, "Write the JSON run report here")->option_text("FILE")->group(kOutput);
  cli::SizeOptions meshSize(*meshCmd, mesh.options.sizing, true);
  meshCmd->add_option("--sizing", mesh.options.sizingFile, "Local sizes: sources in a JSON file (format: docs/sizing.md)")
      ->option_text("FILE")
      ->group(cli::kSizeGroup);
  meshCmd->add_flag("!--no-fragment", mesh.fragment, "Do not make touching solids conformal")->group(kModel);
  meshCmd->add_option("--internal-faces", mesh.options.internalFaces,
                      "Faces inside a solid: crack = two-sided (nodes doubled), bond = one-sided (nodes shared); auto = "
                      "crack where the CAD keeps the face in a shell of its own, bond otherwise")
      ->transform(cli::choice(std::vector<std::pair<std::string, InternalFaces>>{
          {"auto", InternalFaces::Auto}, {"crack", InternalFaces::Crack}, {"bond", InternalFaces::Bond}}))
      ->option_text("auto|crack|bond")
      ->default_str("auto")
      ->group(kModel);
  addOverlapsOption(*meshCmd, mesh.overlaps);
  meshCmd->add_option("--threads", mesh.options.threads, "Threads (0 = all cores); the mesh is the same for any number")
      ->check(CLI::Range(0, 4096))
      ->option_text("N")
      ->default_str("0")
      ->group(kPerformance);
  meshCmd->add_option("--max-elements", mesh.options.maxElements,
                      "Element budget (triangles, plus tets in 3D) checked before meshing; over it the finest sizes are "
                      "coarsened, or the run stops (exit 2). Default: the machine's memory / bytes per element")
      ->check(CLI::PositiveNumber)
      ->option_text("N")
      ->group(kPerformance);
  meshCmd->add_option("--time-limit", mesh.timeLimit, "Stop after S seconds: status failed, exit 3, no mesh (0 = none)")
      ->check(CLI::NonNegativeNumber)
      ->option_text("S")
      ->group(kPerformance);
  messages.add(*meshCmd);
  meshCmd->fallthrough();

  cli::SizingArgs sizing;
  sizing.params = SizingParameters::forAnalysis();
  CLI::App* sizingCmd = app.add_subcommand("sizing", "Write the initial size field (the metric) as VTU, to see the sizes");
  sizingCmd->footer(kUnits);
  sizingCmd->add_option("FILE", sizing.file, "STEP, IGES, BREP or .json analytic model")->required();
  sizingCmd->add_option("-o,--output", sizing.output, "Output .vtu file")->option_text("FILE")->required()->group(kOutput);
  sizingCmd->add_option("--face", sizing.face, "Only this face (1-based), in its parametric plane")
      ->check(CLI::PositiveNumber)
      ->option_text("N")
      ->group(kOutput);
  cli::SizeOptions sizingSize(*sizingCmd, sizing.params, false);
  sizingCmd->add_option("--sizing", sizing.sizingFile, "Local sizes: sources in a JSON file (format: docs/sizing.md)")
      ->option_text("FILE")
      ->group(cli::kSizeGroup);
  sizingCmd->add_flag("!--no-fragment", sizing.fragment, "Do not make touching solids conformal")->group(kModel);
  messages.add(*sizingCmd);
  sizingCmd->fallthrough();

  cli::CheckArgs check;
  CLI::App* checkCmd = app.add_subcommand("check", "Check a mesh file: counts, closed/manifold/oriented, inverted elements, quality");
  checkCmd->add_option("MESH", check.file, "MSH, INP, VTU, STL, OBJ or OFF file")->required();
  checkCmd->add_flag("--json", check.json, "One JSON object on stdout")->group(kOutput);
  messages.add(*checkCmd);
  checkCmd->fallthrough();

  cli::AdaptOptions adapt;
  CLI::App* adaptCmd = cli::addAdaptCommand(app, adapt);
  // adapt keeps the thesis' sizing table: the field's metric decides the sizes
  cli::SizeOptions adaptSize(*adaptCmd, adapt.args.mesh.options.sizing, false);
  messages.add(*adaptCmd);

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
    const std::string unknown = cli::unknownOptionMessage(app, argc, argv);
    const std::string command = argc > 1 && argv[1][0] != '-' ? std::string(argv[1]) + " " : std::string();
    std::fprintf(stderr, "anisomesh: %s (see anisomesh %s--help)\n", unknown.empty() ? e.what() : unknown.c_str(),
                 command.c_str());
    return 2;
  }
  setLogSink(std::make_shared<cli::TerminalSink>(messages.quiet ? -1 : messages.verbose, messages.progress));

  try {
    if (meshCmd->parsed()) meshSize.resolve();
    if (sizingCmd->parsed()) sizingSize.resolve();
    if (adaptCmd->parsed()) adaptSize.resolve();
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
