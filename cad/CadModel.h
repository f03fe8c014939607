#pragma once
// CadModel — a CAD file read through OpenCASCADE, behind an interface that does not expose
// OCCT (the CLI and the tests include this header without OCCT's include path).
//
//   CadModel m = CadModel::read("part.step");   // throws InputError naming the file
//   ShapeSummary before = m.summary();          // what OCCT read, no healing
//   PrepareReport r = m.prepare(opts);          // fix, sew, fragment (conformal assemblies)
//   Model model = m.topology();                 // the mesher's view (mesher/model/Model.h)
//
// OCCT exceptions never escape: they become InputError (reading) or MeshingError. OCCT runs
// in child processes (cad/detail/ChildProcess.h): a crash of the kernel (SIGSEGV) while
// reading makes read() try the next reader path, and while preparing costs that step.
#include <memory>
#include <string>
#include <vector>

#include "mesher/core/Types.h"
#include "mesher/model/Model.h"

namespace aniso {
class CancelToken;  // mesher/core/Cancel.h
}

namespace aniso::cad {

enum class CadFormat { Step, Iges, Brep };
const char* formatName(CadFormat f);

struct SolidSummary {
  int id = 0;           ///< 1-based, MapShapes order
  std::string name;     ///< part name from STEP, else "SOLID<id>"
  double volume = 0;
  std::string color;    ///< the part's colour in STEP ("#rrggbb"), "" when the file gives none
};

/// Counts and measures of a shape, entities counted once each (TopExp::MapShapes).
struct ShapeSummary {
  int solids = 0, shells = 0, faces = 0, edges = 0, vertices = 0;
  double volume = 0;  ///< sum of the solids' volumes
  double area = 0;    ///< area of every face occurrence (OCCT GProp of the whole shape)
  double uniqueFaceArea = 0;  ///< area of every distinct face once
  double exposedArea = 0;     ///< area of the faces bounding exactly one solid (the outer
                              ///< boundary of the union when the solids are conformal)
  Box3 bbox;
  std::vector<SolidSummary> solidList;
};

/// What fragmenting does with solids that overlap (--overlaps).
enum class OverlapPolicy {
  Merge,  ///< fragment anyway: each common region is meshed once, in one part (OverlapRule.h)
  Keep,   ///< leave the whole shape unfragmented (overlapping, unconnected meshes), with a warning
  Error,  ///< refuse the model: InputError naming the first pair and its overlap volume
};

/// "merge", "keep", "error" (the --overlaps values).
const char* overlapPolicyName(OverlapPolicy p);

struct PrepareOptions {
  bool fix = true;        ///< ShapeFix on the whole shape
  bool sew = true;        ///< sew loose faces into shells (tolerance relative to model size)
  bool fragment = true;   ///< general fuse of the solids: conformal interfaces (--no-fragment)
  OverlapPolicy overlaps = OverlapPolicy::Merge;
  /// Sewing tolerance as a fraction of the bounding-box diagonal.
  double sewRelTolerance = 1e-5;
  /// Stops a step under way (its child process is killed): Cancelled naming the step.
  const CancelToken* cancel = nullptr;
};

/// Two solids that overlap: ids are 1-based, in the order of the shape fragmented (as read).
struct Overlap {
  int a = 0, b = 0;  ///< a < b
  std::string nameA, nameB;
  double volume = 0;    ///< volume of their common region(s)
  int assignedTo = 0;   ///< a or b: the part that keeps the common region (0: neither, see
                        ///< OverlapRule.h; always 0 unless the policy is Merge)
};

/// Crosses a process boundary (cad/PrepareIsolated.cpp encodes it): a new field must be
/// added to encode() and decode() there.
struct PrepareReport {
  int facesSewn = 0;                                ///< loose faces joined into shells
  int sharedFaces = 0;                              ///< faces used by two solids after fragmenting
  double fuzzyValue = 0;                            ///< the general fuse's fuzzy value (model units)
  std::vector<Overlap> overlaps;                    ///< pairs of overlapping solids, by (a, b)
  /// Solids (1-based, as prepared) left out of the fragmenting because the fuse failed on
  /// them: meshed on their own, not conformal with the parts they touch.
  std::vector<int> unfusedSolids;
  /// Volume the solids as read counted more than once because their own faces overlap (a
  /// wire whose legs interpenetrate): the rebuild keeps it once (PrepareSelfIntersections).
  double selfOverlapVolume = 0;
  std::vector<std::string> warnings;
};

class CadModel {
 public:
  /// Reads a STEP, IGES or BREP file. The reader is chosen by the file's content first
  /// (STEP "ISO-10303-21", IGES's 80-column S/G/D/P/T records, BREP's "DBRep_DrawableShape"
  /// or "CASCADE Topology"), by extension second. Throws InputError with a one-line message
  /// naming the file for a missing, unreadable, empty, non-CAD or shapeless file. STEP is
  /// read through XCAF (part names and colours, face names and colours: FaceCatalog.h), else the plain reader, else root by root skipping the
  /// roots that fail; what was given up is logged as a warning. When every path crashes
  /// or fails: InputError "...: OpenCASCADE could not read this STEP file (...)".
  /// With `cancel`, a read still running when the token stops is killed: Cancelled
  /// ("... during reading").
  static CadModel read(const std::string& path, const CancelToken* cancel = nullptr);

  CadModel(CadModel&&) noexcept;
  CadModel& operator=(CadModel&&) noexcept;
  ~CadModel();

  const std::string& path() const;
  CadFormat format() const;
  /// The length unit the file declares, in lower case ("inch", "millimetre"; "" when it
  /// says none, and for BREP). Lengths are in mm whatever it is (OCCT converts on reading).
  const std::string& fileUnit() const;
  /// Solids the file declares that reading could not give as solids, not even rebuilt from
  /// their faces (a STEP solid bounded by an open shell that does not close, or one OCCT's
  /// transfer dropped): their faces, if any were read, are loose faces. 0 for IGES and BREP.
  int solidsLost() const;

  /// Summary of the current shape (as read, or as prepared after prepare()).
  ShapeSummary summary() const;

  /// Healing and conformal assembly (see PrepareOptions). Throws MeshingError if OCCT
  /// fails in a way that leaves no usable shape.
  PrepareReport prepare(const PrepareOptions& options);

  /// The mesher's topology of the current shape.
  Model topology() const;

  /// Writes the current shape as BREP (for debugging and for the FreeCAD macro's tests).
  void writeBrep(const std::string& path) const;

  struct Impl;  // holds the TopoDS_Shape and the part names (cad/detail/CadModelImpl.h)
  Impl& impl() { return *impl_; }
  const Impl& impl() const { return *impl_; }

 private:
  explicit CadModel(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace aniso::cad
