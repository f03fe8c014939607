#pragma once
// Internal: the three readers. Each fills impl.shape (and impl's part names for STEP) or
// throws InputError naming the file; none lets an OCCT exception escape.
#include <string>

#include <STEPControl_Reader.hxx>
#include <XSControl_Reader.hxx>

#include "cad/detail/CadModelImpl.h"

namespace aniso::cad::detail {

/// STEP through the ladder XCAF -> plain -> root by root, each in a child process; throws
/// InputError when every path crashed or failed (or the file is not STEP).
void readStep(CadModel::Impl& impl);
/// The rungs, run in the calling process. XCAF: part names in impl.names. Each returns ""
/// or what the transfer lost (lostSolids).
std::string readStepXcaf(CadModel::Impl& impl);
/// STEPControl_Reader, all roots at once, no names.
std::string readStepPlain(CadModel::Impl& impl);
/// STEPControl_Reader one root at a time with OCCT's signals turned into exceptions
/// (OSD::SetSignal, for the child process only): a root that fails or crashes is skipped.
/// Returns "" or what was lost ("skipped root(s) 2, 5 of 7; 3 of 40 solid(s) could not be
/// transferred": OCCT's transfer drops an entity that raised); throws when no root could
/// be transferred.
std::string readStepRoots(CadModel::Impl& impl);
void readIges(CadModel::Impl& impl);
void readBrep(CadModel::Impl& impl);

/// Loads the STEP file into `reader` (ReadFile; a file opening with a UTF-8 byte order mark,
/// which OCCT 7.6's parser refuses, is read from a stream past the mark). Throws InputError
/// naming the file when OCCT cannot parse it.
void loadStepFile(XSControl_Reader& reader, const std::string& path);

/// When `shape` has fewer distinct solids than the file loaded in `reader` has solid B-reps
/// (OCCT's transfer drops an entity that raised, or keeps only the faces of a solid written
/// over an open shell), first rebuilds what it can (rebuildLostSolids), then returns what the
/// user should know, in plain words: "k of n solid(s) ... rebuilt as solid(s) from their
/// faces" and/or "k of n solid(s) could not be transferred (...)"; else "". `notRebuilt`, if
/// given, receives the number of solids still missing.
std::string lostSolids(XSControl_Reader& reader, TopoDS_Shape& shape, int* notRebuilt = nullptr);

/// The FACE entities (ADVANCED_FACE, FACE_SURFACE, ...) of the file loaded in `reader`,
/// whether or not a shape uses them.
int stepFaceCount(XSControl_Reader& reader);

/// The length unit(s) the STEP file loaded in `reader` declares for its shapes, in lower
/// case ("inch", "millimetre"; several joined by ", "); "" when it declares none.
std::string stepFileUnit(STEPControl_Reader& reader);

/// Makes solids again of the faces outside any solid in `shape` when, sewn with a tolerance
/// of 1e-6 of their extent, they form closed shells, at least one and at most `lost` of
/// them: each becomes a solid turned outward (ShapeFix_Solid) if it encloses a volume. The
/// shape then becomes a compound of its solids, the rebuilt ones, the other loose faces and
/// its free edges and vertices. Returns the number rebuilt (0: shape unchanged).
int rebuildLostSolids(TopoDS_Shape& shape, int lost);

/// Takes the solids that hold no face out of impl.shape (BRepTools_ReShape), adds them to
/// impl.solidsLost with a read warning naming them, and binds every other solid's name
/// ("SOLID<id>" by its place as read, when the file names none) so that ids and names do not
/// shift. Returns how many were taken out.
int dropEmptySolids(CadModel::Impl& impl);

/// Removes OCCT's default console printers once, so that library code prints nothing.
void silenceOcctMessages();

}  // namespace aniso::cad::detail
