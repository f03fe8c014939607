#include "tools/cli/SizeOptions.h"

#include <cmath>
#include <string>

#include "mesher/core/Error.h"

namespace aniso::cli {
namespace {

constexpr const char* kGroup = kSizeGroup;
constexpr const char* kShape = "Element shape and grading";

std::string number(double x) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%g", x);
  return buf;
}

}  // namespace

SizeOptions::SizeOptions(CLI::App& cmd, SizingParameters& s, bool volumeIsotropic) : cmd_(cmd), params_(s) {
  const std::string epc = number(elementsPerCircleForCurvatureRatio(s.curvatureRatio));
  cmd.add_option("--size", s.size,
                 "Target element size everywhere; curved faces and thin parts still get smaller elements "
                 "(see --no-curvature)")
      ->option_text("H")
      ->group(kGroup);
  cmd.add_option("--hmax", s.hmax, "Largest element size: a bound every size source respects")->option_text("H")->group(kGroup);
  cmd.add_option("--hmin", s.hmin, "Smallest element size: a bound every size source respects")->option_text("H")->group(kGroup);
  cmd.add_option("--hmax-rel", s.hmaxRel, "Largest element size as a fraction of the model's bounding-box diagonal")
      ->option_text("F")
      ->default_str(number(s.hmaxRel))
      ->group(kGroup);
  cmd.add_option("--hmin-rel", s.hminRel, "Smallest element size as a fraction of the model's bounding-box diagonal")
      ->option_text("F")
      ->default_str(number(s.hminRel))
      ->group(kGroup);
  cmd.add_option("--elements-per-circle", elementsPerCircle_,
                 "Curvature: elements per full circle on curved faces and edges (Gmsh's -clcurv)")
      ->option_text("N")
      ->default_str(epc)
      ->group(kGroup);
  cmd.add_option("--curvature-ratio", s.curvatureRatio,
                 "Curvature as edge length / curvature radius (2π / elements per circle; thesis γ_c)")
      ->option_text("R")
      ->default_str(number(s.curvatureRatio))
      ->group(kGroup);
  cmd.add_flag("--no-curvature", noCurvature_, "Ignore curvature: the target size (--size or --hmax) on curved faces too")
      ->group(kGroup);
  cmd.add_option("--chord-deviation-rel", s.chordDeviationRel,
                 "Curvature: largest distance of an element edge from a curved face or edge, as a fraction of the "
                 "model's bounding-box diagonal; 0 = elements per circle only")
      ->option_text("F")
      ->default_str(number(s.chordDeviationRel))
      ->group(kGroup);
  cmd.add_option("--gradation", s.gradation, "How fast sizes may grow between neighbours (thesis γ_M; ≥ 1)")
      ->option_text("G")
      ->default_str(number(s.gradation))
      ->group(kShape);
  const std::string anisotropyDefault =
      volumeIsotropic ? "default 1; " + number(s.anisotropy) + " gives the thesis' stretched surface meshes"
                      : "default " + number(s.anisotropy);
  cmd.add_option("--anisotropy", s.anisotropy,
                 "Largest stretch of an element (1 = isotropic); " + anisotropyDefault + " (thesis γ_a)")
      ->option_text("A")
      ->group(kShape);
  cmd.add_option("--contour-anisotropy", s.contourAnisotropy, "Largest stretch along curved edges (thesis γ_ac)")
      ->option_text("A")
      ->default_str(number(s.contourAnisotropy))
      ->group(kShape);
}

bool SizeOptions::given(const char* name) const { return cmd_.count(name) > 0; }

void SizeOptions::resolve() {
  auto refuse = [](const std::string& sentence) { throw InputError(sentence); };
  if (given("--size") && given("--hmax"))
    refuse("--size and --hmax both set the largest size: give one of them (--size H is the target, --hmax H only a bound)");
  if (given("--hmax") && given("--hmax-rel")) refuse("--hmax and --hmax-rel both set the largest size: give one of them");
  if (given("--size") && given("--hmax-rel")) refuse("--size and --hmax-rel both set the largest size: give one of them");
  if (given("--hmin") && given("--hmin-rel")) refuse("--hmin and --hmin-rel both set the smallest size: give one of them");
  if (given("--elements-per-circle") && given("--curvature-ratio"))
    refuse("--elements-per-circle and --curvature-ratio both set the curvature (ratio = 2π / elements): give one of them");
  if (noCurvature_ && (given("--elements-per-circle") || given("--curvature-ratio")))
    refuse("--no-curvature turns the curvature off: drop it or drop --elements-per-circle / --curvature-ratio");
  if (elementsPerCircle_ && !(std::isfinite(*elementsPerCircle_) && *elementsPerCircle_ >= 1 && *elementsPerCircle_ <= 1e4))
    refuse("--elements-per-circle must be a number from 1 to 10000 (Gmsh's default with -clcurv is 12)");
  if (elementsPerCircle_) params_.curvatureRatio = curvatureRatioForElementsPerCircle(*elementsPerCircle_);
  params_.curvature = !noCurvature_;
  const std::string bad = params_.check();
  if (!bad.empty()) refuse(bad);
}

}  // namespace aniso::cli
