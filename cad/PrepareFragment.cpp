#include <BRepAlgoAPI_BuilderAlgo.hxx>
#include <BRepBuilderAPI_Copy.hxx>
#include <BRepLib.hxx>
#include <Precision.hxx>
#include <ShapeFix_ShapeTolerance.hxx>
#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Standard_Failure.hxx>
#include <TopExp.hxx>
#include <TopTools_DataMapOfShapeInteger.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <ShapeBuild_ReShape.hxx>
#include <ShapeFix_Wireframe.hxx>
#include <TopoDS_Compound.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>

#include "cad/OverlapRule.h"
#include "cad/detail/FaceTags.h"
#include "cad/detail/Prepare.h"
#include "mesher/core/Error.h"

namespace aniso::cad::detail {
namespace {

/// Fuzzy value of the general fuse, relative to the diagonal: at least kFuzzyMinRel (parts
/// that touch exactly rarely do in exported files), at most kFuzzyMaxRel (nothing visible
/// collapses, and edges grown by a larger fuzzy value leave face loops open: measured on
/// Relay_15.2x19.0mm and Push_SMD_RA_4.5x3.4mm, 1e-4 refused both), in between the model's own
/// largest vertex/edge tolerance.
constexpr double kFuzzyMinRel = 1e-7;
constexpr double kFuzzyMaxRel = 1e-6;
/// When no fuse at those values is trusted with every solid in it, and the model's own
/// tolerance is larger, the fuse is tried once more at that tolerance, at most this
/// fraction of the diagonal, and kept when it leaves fewer solids out (its result passes
/// the same volume and face checks). Ag9900M_MT (NX, vertex tolerances up to 0.5 mm on a
/// 31 mm diagonal): at 3e-5 the fuse fails and 11 solids are left out (exposed area +9 %);
/// at 0.03, 6 (+0.65 %); at 0.01, 15 break.
constexpr double kFuzzyLooseRel = 1e-3;
/// A fuse is trusted when every solid's images add up to its volume within this fraction,
/// plus the layer the fuzzy value may move (fuzzy × area).
constexpr double kImageVolumeRel = 1e-3;
/// ... plus this fraction of the whole assembly's volume: a small part whose B-spline faces
/// the fuse retrims may change by a fraction of a percent of itself (measured on
/// Ag9900M_MT: 0.2-0.4 % of 0.7-2 mm³ parts, 1e-6-1e-5 of the assembly) without a change
/// any mesh or measure of the assembly could see.
constexpr double kAssemblyVolumeRel = 1e-5;
/// The two absolute terms above (the fuzzy layer, the assembly's share) may excuse at most
/// this fraction of a solid's own volume: at a loose fuzzy value they grew larger than a
/// small part (KiCad's Breve TEZ transformer at fuzzy 0.086: 13 pins of 2.5 mm³ allowed
/// 2 mm³ each, and 9 came out of the fuse with 15 % of their volume, trusted).
constexpr double kImageSlackCapRel = 0.02;
/// When no fuzzy value gives a trusted fuse, the solid the check names is left out of it
/// (meshed on its own, reported) and the fuse runs again, for at most this share of the
/// solids and this many fuses (each costs a whole fuse): defective parts (solids whose faces
/// do not close, which the fuse empties) must not leave a whole assembly unfused. Measured:
/// Ag9900M_MT (35 solids, 88 open loops), solid 6 lost 91 % of its volume at both fuzzy
/// values; with the assembly slack above, 6 solids are left out (without it, 11 were left
/// out and the fuse still failed on a 12th).
constexpr double kMaxUnfusedShare = 0.34;
constexpr int kMaxUnfusedSolids = 12;
/// Before a solid the check names is left out, it is tried once with its wires mended
/// (ShapeFix_Wireframe: gaps between consecutive edges closed, then small edges removed, at
/// the fuzzy value), kept when that changes its volume by at most this fraction. OCCT's fuse
/// trips over such gaps (BOPAlgo_AlertTooSmallEdge) in a way that depends on the other
/// arguments: measured on Ag9900M_MT (88 loops open), solid 6 fused with either neighbour
/// alone keeps its volume, with both it lost 91 %; mended (volume −0.14 %), the three fuse
/// within 0.03 %.
constexpr double kWireFixVolumeRel = 5e-3;

/// The solids an argument became in the general fuse (itself when untouched).
TopTools_IndexedMapOfShape imagesOf(BRepAlgoAPI_BuilderAlgo& gf, const TopoDS_Shape& solid) {
  TopTools_IndexedMapOfShape out;
  if (gf.IsDeleted(solid)) return out;
  const TopTools_ListOfShape& mod = gf.Modified(solid);
  if (mod.IsEmpty()) {
    out.Add(solid);
  } else {
    for (const TopoDS_Shape& s : mod) TopExp::MapShapes(s, TopAbs_SOLID, out);
  }
  return out;
}

/// The arguments of the fuse (1-based, as the shape's solids) and their measures.
struct Arguments {
  TopTools_IndexedMapOfShape solids;  ///< a solid repaired for the fuse replaces its original
  TopTools_IndexedMapOfShape originals;  ///< the shape's solids
  std::vector<double> volume, area;  ///< indexed by id, [0] unused
  double total = 0;                  ///< sum of |volume|
  /// Faces of each argument the mesher's rule finds wanting before the fuse
  /// (flawedFaceCounts), by id; empty until a fuse needs them (and after a repair).
  std::vector<int> flaws;
};

/// The arguments' flawed faces before the fuse (Arguments::flaws), measured once.
const std::vector<int>& flawsBefore(Arguments& args) {
  if (!args.flaws.empty()) return args.flaws;
  const int n = args.solids.Extent();
  TopoDS_Compound all;
  BRep_Builder b;
  b.MakeCompound(all);
  std::vector<TopTools_IndexedMapOfShape> parts(static_cast<std::size_t>(n) + 1);
  for (int i = 1; i <= n; ++i) {
    b.Add(all, args.solids(i));
    parts[static_cast<std::size_t>(i)].Add(args.solids(i));
  }
  args.flaws = flawedFaceCounts(all, parts);
  return args.flaws;
}

/// One general fuse: the images of every argument (1-based), or why it is not trusted.
struct Fuse {
  std::unique_ptr<BRepAlgoAPI_BuilderAlgo> gf;
  std::vector<TopTools_IndexedMapOfShape> images;
  std::vector<char> excluded;  ///< per argument (1-based): left out, its image is itself
  std::string failure;  ///< empty: done and trusted
  int failedSolid = 0;  ///< the argument the volume check named (0: none)
  /// The arguments whose faces came out of the fuse with more flaws than they went in
  /// (flawedFaceCounts): the fuse is not trusted; they are left out of the next one.
  std::vector<int> broken;
  /// Arguments whose images differ from their volume by more than kImageVolumeRel (within
  /// the slack): (id, relative change).
  std::vector<std::pair<int, double>> changed;
};

Fuse runFuse(Arguments& args, double fuzzy, const std::vector<char>& excluded) {
  Fuse f;
  f.excluded = excluded;
  try {
    f.gf = std::make_unique<BRepAlgoAPI_BuilderAlgo>();
    TopTools_ListOfShape list;
    for (int i = 1; i <= args.solids.Extent(); ++i)
      if (!excluded[i]) list.Append(args.solids(i));
    f.gf->SetArguments(list);
    f.gf->SetRunParallel(false);  // determinism
    f.gf->SetNonDestructive(true);
    f.gf->SetFuzzyValue(fuzzy);
    f.gf->Build();
    if (f.gf->HasErrors() || !f.gf->IsDone()) {
      f.failure = "the general fuse reported errors";
      return f;
    }
    f.images.resize(static_cast<size_t>(args.solids.Extent()) + 1);
    for (int i = 1; i <= args.solids.Extent(); ++i) {
      if (excluded[i]) {
        f.images[i].Add(args.solids(i));
        continue;
      }
      f.images[i] = imagesOf(*f.gf, args.solids(i));
      double v = 0;
      for (int k = 1; k <= f.images[i].Extent(); ++k) v += solidVolume(f.images[i](k));
      const double own = std::abs(args.volume[i]);
      const double slack =
          kImageVolumeRel * own + std::min(fuzzy * args.area[i] + kAssemblyVolumeRel * args.total, kImageSlackCapRel * own);
      if (own > 0 && std::abs(v - args.volume[i]) > kImageVolumeRel * own)
        f.changed.push_back({i, std::abs(v - args.volume[i]) / own});
      if (std::abs(v - args.volume[i]) > slack) {
        f.failure = "solid " + std::to_string(i) + " became volume " + num(v) + " instead of " + num(args.volume[i]);
        f.failedSolid = i;
        return f;
      }
    }
    // the mesher must be able to read what the fuse made of each solid
    const std::vector<int>& before = flawsBefore(args);
    std::vector<TopTools_IndexedMapOfShape> fused(f.images.size());  // left-out solids: not in the result
    for (int i = 1; i <= args.solids.Extent(); ++i)
      if (!excluded[i]) fused[static_cast<std::size_t>(i)] = f.images[i];
    const std::vector<int> after = flawedFaceCounts(f.gf->Shape(), fused);
    for (int i = 1; i <= args.solids.Extent(); ++i)
      if (!excluded[i] && after[static_cast<std::size_t>(i)] > before[static_cast<std::size_t>(i)]) f.broken.push_back(i);
    if (!f.broken.empty())
      f.failure = std::to_string(f.broken.size()) + " solid(s) came out with faces whose boundaries no longer close";
  } catch (const Standard_Failure& e) {
    f.failure = std::string("OpenCASCADE: ") + e.GetMessageString();
  }
  return f;
}

/// The shape's largest vertex or edge tolerance; 0 when OCCT cannot tell.
double largestTolerance(const TopoDS_Shape& shape) {
  try {
    return std::max(BRep_Tool::MaxTolerance(shape, TopAbs_VERTEX), BRep_Tool::MaxTolerance(shape, TopAbs_EDGE));
  } catch (const Standard_Failure&) {
    return 0;
  }
}

/// The fuzzy values to try, the model's first.
std::vector<double> fuzzyValues(const TopoDS_Shape& shape, double diag) {
  const double tol = largestTolerance(shape);
  const double lo = kFuzzyMinRel * diag;
  const double model = std::clamp(tol, lo, kFuzzyMaxRel * diag);
  if (model > lo) return {model, lo};
  return {lo};
}

/// The fuzzy value of a last try for a model exported with a loose tolerance: its largest
/// vertex/edge tolerance, at most kFuzzyLooseRel of the diagonal; 0 when that is not above
/// the values of fuzzyValues (nothing new to try).
double looseFuzzy(const TopoDS_Shape& shape, double diag) {
  const double loose = std::min(largestTolerance(shape), kFuzzyLooseRel * diag);
  return loose > kFuzzyMaxRel * diag ? loose : 0;
}

/// The result solids that are images of several arguments, each with its arguments.
std::vector<CommonRegion> commonRegions(const Fuse& f, int n, TopTools_IndexedMapOfShape& regionSolids) {
  TopTools_DataMapOfShapeInteger firstOwner;
  std::vector<CommonRegion> regions;
  for (int i = 1; i <= n; ++i)
    for (int k = 1; k <= f.images[i].Extent(); ++k) {
      const TopoDS_Shape& im = f.images[i](k);
      if (!firstOwner.IsBound(im)) {
        firstOwner.Bind(im, i);
        continue;
      }
      const int r = regionSolids.FindIndex(im);
      if (r == 0) {
        regionSolids.Add(im);
        regions.push_back({{firstOwner.Find(im), i}, solidVolume(im), 0, {}, 0});
      } else {
        regions[static_cast<size_t>(r - 1)].parts.push_back(i);
      }
    }
  return regions;
}

/// The new shape: each argument's solids in argument order (the images it keeps, merged
/// into one solid where it keeps common regions), then whatever was not in a solid.
void assembleParts(CadModel::Impl& impl, const Arguments& args, const Fuse& f,
                   const TopTools_IndexedMapOfShape& regionSolids, const std::vector<CommonRegion>& regions,
                   PrepareReport& report) {
  BRep_Builder b;
  TopoDS_Compound c;
  b.MakeCompound(c);
  int added = 0;  // solids in c: the 1-based id of the next one, less one
  for (int i = 1; i <= args.solids.Extent(); ++i) {
    const TopoDS_Shape key = args.originals(i).Located(TopLoc_Location());
    const bool named = impl.nameIndex.IsBound(key);
    const int name = named ? impl.nameIndex.Find(key) : -1;
    TopTools_ListOfShape pieces;
    bool keepsRegion = false;
    for (int k = 1; k <= f.images[i].Extent(); ++k) {
      const int r = regionSolids.FindIndex(f.images[i](k));
      if (r > 0 && regions[static_cast<size_t>(r - 1)].owner != i) continue;
      keepsRegion = keepsRegion || r > 0;
      pieces.Append(f.images[i](k));
    }
    const TopTools_ListOfShape solids = keepsRegion ? mergePieces(pieces, args.volume[i]) : pieces;
    if (keepsRegion && solids.Extent() > 1)
      report.warnings.push_back(impl.solidName(args.originals(i), i) + " (solid " + std::to_string(i) +
                                ") is " + std::to_string(solids.Extent()) + " solids after fragmenting");
    for (const TopoDS_Shape& s : solids) {
      b.Add(c, s);
      ++added;
      if (f.excluded[i]) report.unfusedSolids.push_back(added);
      if (named) impl.nameIndex.Bind(s.Located(TopLoc_Location()), name);
    }
  }
  addLooseFaces(impl.shape, args.originals, c);
  impl.shape = c;
  // face tags: from the arguments of the fuse (a solid mended for it already carries them)
  TopoDS_Compound fused;
  b.MakeCompound(fused);
  for (int i = 1; i <= args.solids.Extent(); ++i) b.Add(fused, args.solids(i));
  carryFaceTags(impl, fused, [&f](const TopoDS_Shape& face) { return historyImages(f.gf->History(), face); });
  dropStaleFaceTags(impl);
}

int countSharedFaces(const TopoDS_Shape& shape) {
  TopTools_IndexedDataMapOfShapeListOfShape faceSolids;
  TopExp::MapShapesAndAncestors(shape, TopAbs_FACE, TopAbs_SOLID, faceSolids);
  int shared = 0;
  for (int i = 1; i <= faceSolids.Extent(); ++i) {
    TopTools_IndexedMapOfShape distinct;
    for (const TopoDS_Shape& s : faceSolids(i)) distinct.Add(s);
    if (distinct.Extent() >= 2) ++shared;
  }
  return shared;
}

/// When the fuse of all the solids fails without naming one (OCCT's builder reports an
/// error for the whole run, e.g. BOPAlgo_AlertBuilderFailed), the solids to leave out are
/// found by fusing pairs: every two solids whose boxes (grown by the fuzzy value) meet are
/// fused alone, and a pair fails when that fuse is not trusted. Solids are left out
/// greedily, the one in most failing pairs first (the smaller boundary on a tie), until no
/// failing pair is left. Empty when every pair fuses (the failure is not between two
/// solids) or more than maxOut would go. Cost: one small fuse per pair that touches.
/// Measured on Ag9900M_MT (35 solids, 51 pairs touch, 4 s): 2 pairs fail with OCCT errors,
/// 25 break faces; 11 solids cover them (weighting by area would need more than
/// kMaxUnfusedSolids: the board fails with 13 small parts).
std::vector<int> pairCulprits(Arguments& args, double fuzzy, const std::vector<char>& excluded, int maxOut) {
  const int n = args.solids.Extent();
  std::vector<Bnd_Box> box(static_cast<std::size_t>(n) + 1);
  for (int i = 1; i <= n; ++i) {
    if (excluded[i]) continue;
    try {
      BRepBndLib::Add(args.solids(i), box[i], /*useTriangulation=*/false);
    } catch (const Standard_Failure&) {
      box[i].SetWhole();
    }
    box[i].Enlarge(fuzzy);
  }
  std::vector<std::pair<int, int>> failing;
  for (int i = 1; i <= n; ++i)
    for (int j = i + 1; j <= n; ++j) {
      if (excluded[i] || excluded[j] || box[i].IsOut(box[j])) continue;
      std::vector<char> only(static_cast<std::size_t>(n) + 1, 1);
      only[i] = only[j] = 0;
      if (!runFuse(args, fuzzy, only).failure.empty()) failing.emplace_back(i, j);
    }
  std::vector<int> out;
  while (!failing.empty()) {
    std::vector<int> count(static_cast<std::size_t>(n) + 1, 0);
    for (const auto& [i, j] : failing) ++count[i], ++count[j];
    int c = 0;
    for (int k = 1; k <= n; ++k)
      if (count[k] > 0 && (c == 0 || count[k] > count[c] || (count[k] == count[c] && args.area[k] < args.area[c]))) c = k;
    if (static_cast<int>(out.size()) == maxOut) return {};
    out.push_back(c);
    std::erase_if(failing, [c](const std::pair<int, int>& p) { return p.first == c || p.second == c; });
  }
  return out;
}

/// Argument i with its wires mended (kWireFixVolumeRel); false when the fix changes
/// nothing, fails, or changes the volume too much. The mended faces take the face tags.
bool mendWires(CadModel::Impl& impl, Arguments& args, int i, double precision) {
  try {
    Handle(ShapeFix_Wireframe) fix = new ShapeFix_Wireframe(args.solids(i));
    fix->SetPrecision(precision);
    const bool gaps = fix->FixWireGaps();
    const bool small = fix->FixSmallEdges();
    if (!gaps && !small) return false;
    const TopoDS_Shape fixed = fix->Shape();
    if (fixed.IsNull() || fixed.ShapeType() != TopAbs_SOLID) return false;
    const double v = solidVolume(fixed);
    if (std::abs(v - args.volume[i]) > kWireFixVolumeRel * std::abs(args.volume[i])) return false;
    const Handle(ShapeBuild_ReShape) context = fix->Context();
    carryFaceTags(impl, args.solids(i), [&context](const TopoDS_Shape& f) { return imageList(context->Apply(f)); });
    args.solids.Substitute(i, fixed);
    args.total += std::abs(v) - std::abs(args.volume[i]);
    args.volume[i] = v;
    args.area[i] = shapeArea(fixed);
    args.flaws.clear();
    return true;
  } catch (const Standard_Failure&) {
    return false;
  }
}

/// The arguments as copies whose vertex and edge tolerances are reset to what their geometry
/// needs (BRepLib::SameParameter and UpdateTolerances from Precision::Confusion); none when no
/// tolerance comes down by more than a factor 10 (nothing to gain). The STEP translation
/// inflates tolerances to cover defects (0.85 mm at the 0.18 mm tip of a pin of KiCad's Breve
/// TEZ transformer; 0.44 and 0.92 mm on CHK EI48's pins) and in a fuse those balls swallow
/// what lies within them: the pins came out with 15-20 % of their volume. With their
/// tolerances reset they fuse within 2 %. The copies take the face tags.
std::optional<Arguments> withTightTolerances(CadModel::Impl& impl, const Arguments& args) {
  Arguments tight = args;
  bool lowered = false;
  try {
    for (int i = 1; i <= args.solids.Extent(); ++i) {
      const double before = largestTolerance(args.solids(i));
      BRepBuilderAPI_Copy copy(args.solids(i));  // tolerances live in the shared TShapes
      TopoDS_Shape s = copy.Shape();
      ShapeFix_ShapeTolerance().LimitTolerance(s, Precision::Confusion(), Precision::Confusion());
      BRepLib::SameParameter(s, Precision::Confusion(), Standard_True);
      BRepLib::UpdateTolerances(s, Standard_False);
      lowered = lowered || largestTolerance(s) * 10 < before;
      carryFaceTags(impl, args.solids(i), [&copy](const TopoDS_Shape& f) { return imageList(copy.ModifiedShape(f)); });
      tight.solids.Substitute(i, s);
    }
  } catch (const Standard_Failure&) {
    return std::nullopt;
  }
  if (!lowered) return std::nullopt;
  tight.flaws.clear();
  return tight;
}

Arguments measureArguments(const TopoDS_Shape& shape) {
  Arguments a;
  TopExp::MapShapes(shape, TopAbs_SOLID, a.solids);
  a.originals = a.solids;
  a.volume.assign(static_cast<size_t>(a.solids.Extent()) + 1, 0.0);
  a.area.assign(a.volume.size(), 0.0);
  for (int i = 1; i <= a.solids.Extent(); ++i) {
    a.volume[i] = solidVolume(a.solids(i));
    a.total += std::abs(a.volume[i]);
    a.area[i] = shapeArea(a.solids(i));
  }
  return a;
}

}  // namespace

/// A fuse with the solids it cannot take left out (fuseLeavingOut).
struct Attempt {
  Fuse f;
  double fuzzy = 0;
  std::vector<char> excluded;  ///< per argument (1-based)
  std::string unfused;         ///< the solids left out, "id \"name\", ..."
  int left = 0, repaired = 0;
  bool better(const Attempt& o) const {
    return f.failure.empty() && (!o.f.failure.empty() || left < o.left);
  }
};

/// From the fuse `first` at `fuzzy` that is not trusted: the solids the check names (each
/// failing solid tried once with its wires mended first), or those the fuse broke, or the
/// culprits of failing pairs, left out, and the fuse run again, until it is trusted or
/// kMaxUnfusedShare / kMaxUnfusedSolids would be exceeded.
Attempt fuseLeavingOut(CadModel::Impl& impl, Arguments& args, double fuzzy, Fuse first) {
  const int n = args.solids.Extent();
  Attempt a;
  a.f = std::move(first);
  a.fuzzy = fuzzy;
  a.excluded.assign(static_cast<size_t>(n) + 1, 0);
  std::vector<char> tried(static_cast<size_t>(n) + 1, 0);
  const int maxUnfused = std::min(kMaxUnfusedSolids, static_cast<int>(kMaxUnfusedShare * n));
  for (int k = 0; k < 2 * maxUnfused && !a.f.failure.empty() && n > 2; ++k) {
    std::vector<int> out = a.f.broken;
    if (out.empty() && a.f.failedSolid > 0) {
      const int bad = a.f.failedSolid;
      if (!tried[static_cast<size_t>(bad)]) {
        tried[static_cast<size_t>(bad)] = 1;
        if (mendWires(impl, args, bad, fuzzy)) {
          ++a.repaired;
          a.f = runFuse(args, fuzzy, a.excluded);
          continue;
        }
      }
      out = {bad};
    }
    if (out.empty()) out = pairCulprits(args, fuzzy, a.excluded, maxUnfused - a.left);
    if (out.empty() || a.left + static_cast<int>(out.size()) > maxUnfused) break;
    for (const int bad : out) {
      a.excluded[static_cast<size_t>(bad)] = 1;
      ++a.left;
      a.unfused += (a.unfused.empty() ? "" : ", ") + std::to_string(bad) + " \"" +
                   impl.solidName(args.originals(bad), bad) + "\"";
    }
    a.f = runFuse(args, fuzzy, a.excluded);
  }
  return a;
}

void fragmentSolids(CadModel::Impl& impl, double diag, OverlapPolicy policy, PrepareReport& report) {
  Arguments args = measureArguments(impl.shape);
  const int n = args.solids.Extent();
  if (n < 2) return;
  Fuse f;
  std::string failures;
  const std::vector<char> none(static_cast<size_t>(n) + 1, 0);
  const std::vector<double> fuzzies = fuzzyValues(impl.shape, diag);
  for (const double fuzzy : fuzzies) {
    f = runFuse(args, fuzzy, none);
    if (f.failure.empty()) {
      report.fuzzyValue = fuzzy;
      break;
    }
    failures += (failures.empty() ? "" : "; ") + ("fuzzy " + num(fuzzy) + ": " + f.failure);
  }
  Attempt best;
  best.f = std::move(f);
  best.fuzzy = report.fuzzyValue;
  if (!best.f.failure.empty()) {
    best = fuseLeavingOut(impl, args, fuzzies.front(), std::move(best.f));
    // a model whose own tolerance is looser than the fuzzy values above: once more at it
    const double loose = looseFuzzy(impl.shape, diag);
    if (loose > 0 && (!best.f.failure.empty() || best.left > 0)) {
      Arguments looseArgs = args;  // its own copy: a wire mended for this try stays in it
      Fuse g = runFuse(looseArgs, loose, none);
      Attempt a;
      if (g.failure.empty()) {
        a.f = std::move(g);
        a.fuzzy = loose;
        a.excluded = none;
      } else {
        failures += "; fuzzy " + num(loose) + " (the model's tolerance): " + g.failure;
        a = fuseLeavingOut(impl, looseArgs, loose, std::move(g));
      }
      if (a.better(best)) {
        best = std::move(a);
        args = std::move(looseArgs);
      }
    }
    // once more with the solids' tolerances reset to what their geometry needs
    if (!best.f.failure.empty() || best.left > 0)
      if (std::optional<Arguments> tight = withTightTolerances(impl, args)) {
        Attempt a;
        for (const double fuzzy : fuzzies) {
          a.f = runFuse(*tight, fuzzy, none);
          a.fuzzy = fuzzy;
          a.excluded = none;
          if (a.f.failure.empty()) break;
        }
        if (!a.f.failure.empty()) {
          failures += "; tolerances reset: " + a.f.failure;
          a = fuseLeavingOut(impl, *tight, fuzzies.front(), std::move(a.f));
        }
        if (a.better(best)) {
          best = std::move(a);
          args = std::move(*tight);
          report.warnings.push_back("the solids' vertex and edge tolerances (up to " + num(largestTolerance(impl.shape)) +
                                    ") were reset to what their geometry needs: the fuse failed with them");
        }
      }
    if (best.f.failure.empty()) report.fuzzyValue = best.fuzzy;
  }
  f = std::move(best.f);
  const std::string& unfused = best.unfused;
  const int repaired = best.repaired;
  if (repaired > 0)
    report.warnings.push_back(std::to_string(repaired) + " solid(s) fused after closing gaps in their face boundaries up to " +
                              num(best.fuzzy) + " (the fuse failed on them)");
  if (!f.failure.empty()) {
    if (!unfused.empty()) failures += "; without solid(s) " + unfused + ": " + f.failure;
    report.warnings.push_back("fragmenting the solids failed (" + failures + "); solids are meshed independently");
    return;
  }
  if (!f.changed.empty()) {
    std::sort(f.changed.begin(), f.changed.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
    std::string which;
    for (std::size_t k = 0; k < f.changed.size() && k < 3; ++k)
      which += (k ? ", " : "") + std::to_string(f.changed[k].first) + " \"" +
               impl.solidName(args.originals(f.changed[k].first), f.changed[k].first) + "\"";
    char pct[32];
    std::snprintf(pct, sizeof pct, "%.2g %%", 100 * f.changed.front().second);
    report.warnings.push_back(std::to_string(f.changed.size()) + " solid(s) changed volume in the fuse by up to " + pct +
                              " (" + which + (f.changed.size() > 3 ? ", ..." : "") + ")");
  }
  if (!unfused.empty())
    report.warnings.push_back("solid(s) " + unfused + " could not be fragmented with the others (" + failures +
                              "): meshed on their own, not conformal with the parts they touch");
  if (!failures.empty() && unfused.empty())
    report.warnings.push_back("fragmenting at the model's tolerance failed (" + failures + "); fragmented at fuzzy " +
                              num(report.fuzzyValue));
  TopTools_IndexedMapOfShape regionSolids;
  std::vector<CommonRegion> regions = commonRegions(f, n, regionSolids);
  if (policy == OverlapPolicy::Merge)
    for (int k = 1; k <= regionSolids.Extent(); ++k) {
      CommonRegion& r = regions[static_cast<size_t>(k - 1)];
      r.area = shapeArea(regionSolids(k));
      if (isFilm(r.volume, r.area, diag)) {  // the faces are measured only where the rule uses them
        std::vector<TopoDS_Shape> parts;
        for (const int p : r.parts) parts.push_back(args.solids(p));
        r.width = regionFaceWidths(regionSolids(k), parts, 2 * best.fuzzy);
      }
      r.owner = regionOwner(r, args.volume, diag);
    }
  report.overlaps = overlapPairs(regions);
  for (Overlap& o : report.overlaps) {
    o.nameA = impl.solidName(args.originals(o.a), o.a);
    o.nameB = impl.solidName(args.originals(o.b), o.b);
  }
  if (!regions.empty()) {
    const Overlap& o = report.overlaps.front();
    const std::string pairs = std::to_string(report.overlaps.size()) + " overlapping part pair(s), volume " +
                              num(overlapExcess(regions)) + " in all";
    if (policy == OverlapPolicy::Error)
      throw InputError(impl.path + ": solids " + std::to_string(o.a) + " \"" + o.nameA + "\" and " +
                       std::to_string(o.b) + " \"" + o.nameB + "\" overlap by volume " + num(o.volume) + " (" +
                       pairs + "; --overlaps error)");
    if (policy == OverlapPolicy::Keep) {
      report.warnings.push_back(pairs + "; the solids are not fragmented (--overlaps keep)");
      return;
    }
    report.warnings.push_back(pairs + ", each common region kept in the smaller part (a thin film: in the part that keeps it without narrow faces elsewhere); see the report");
  }
  assembleParts(impl, args, f, regionSolids, regions, report);
  report.sharedFaces = countSharedFaces(impl.shape);
}

}  // namespace aniso::cad::detail
