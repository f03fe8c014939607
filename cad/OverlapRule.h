#pragma once
// Which part keeps a region common to overlapping parts (--overlaps merge), and the pairs
// reported for it. No OCCT: the rule is unit-tested on plain numbers.
//
// Rule: a common region is meshed once, in the part of SMALLEST volume (volumes as read,
// before fragmenting) among the parts that contain it; volumes equal within kVolumeTieRel
// (relative) are a tie, won by the part first in the file (smaller id). So a screw modelled
// inside its threaded hole, a pin pressed into a housing or a coil inside its moulded body
// stays whole, and the larger part loses the common region (it gets a cavity there).
//
// Except for a film: a region thinner than kFilmThicknessRel of the model's diagonal
// (2 × volume / area), as two parts exported a micrometre into each other. Keeping it
// in one part adds the region's faces on that part's boundary to the others, and in a film
// some of those faces are strips as narrow as the film is thick, which only slivers can
// mesh. A film goes to the part whose added faces are the widest (the narrowest of them,
// measured as 2 × area / perimeter), unless the volume rule's choice is within
// kFilmWidthRatio of it: a pin standing 1 µm deep on a body loses its 1 µm tip (its end face
// moves onto the body's face) instead of cutting a 1 µm recess with 1 µm walls into the body.
#include <vector>

#include "cad/CadModel.h"

namespace aniso::cad {

/// Volumes closer than this, relative to the larger, are equal for the rule.
inline constexpr double kVolumeTieRel = 1e-6;

/// A common region thinner than this fraction of the model's diagonal is a film: thinner
/// than the smallest element the sizing allows by default (γ_hmin, MeshOptions::hminRel), so
/// no mesh can resolve a face as narrow as the film. Films exported between parts come well
/// below it; contacts pressed into a housing, inserts and screw threads come above it and
/// keep the volume rule (docs/measurements.md).
inline constexpr double kFilmThicknessRel = 1e-4;
/// A film stays with the volume rule's part unless another part's added faces are wider
/// than its own by more than 1 / kFilmWidthRatio.
inline constexpr double kFilmWidthRatio = 0.5;

/// A solid of the general fuse that is an image of several parts.
struct CommonRegion {
  std::vector<int> parts;  ///< 1-based ids of the parts containing it, ascending, size >= 2
  double volume = 0;
  int owner = 0;           ///< the part that keeps it (regionOwner), 0 until assigned
  /// Per parts[k]: the narrowest face that keeping the region in parts[k] adds to the other
  /// parts (2 × area / perimeter; infinity: none); empty when not measured.
  std::vector<double> width;
  double area = 0;  ///< of the region's boundary; 0 when not measured
};

/// The part of `parts` (1-based ids, non-empty) that keeps their common region by volume;
/// partVolume[id] is the volume of part id (index 0 unused).
int regionOwner(const std::vector<int>& parts, const std::vector<double>& partVolume);

/// Whether a region of this volume and boundary area is a film (kFilmThicknessRel).
bool isFilm(double volume, double area, double diagonal);

/// The part that keeps region `r`: the volume rule, or for a film (r.width and r.area
/// measured) the part whose added faces are the widest, as described above.
int regionOwner(const CommonRegion& r, const std::vector<double>& partVolume, double diagonal);

/// One entry per pair of parts with a common region, sorted by (a, b): volume = the sum of
/// the regions containing both; assignedTo = the one of a, b that keeps most of that volume
/// (0 when every such region went to a third part or is unassigned). Names are left empty.
std::vector<Overlap> overlapPairs(const std::vector<CommonRegion>& regions);

/// The volume counted more than once by the parts: sum over regions of (parts - 1) × volume
/// (= the parts' total volume minus the union's).
double overlapExcess(const std::vector<CommonRegion>& regions);

/// How far the prepared solids' volume `after` is from the volume as read `before` less the
/// overlaps merged (each region kept once, in one part): (after − expected) / before; 0 when
/// before is not positive. A repair that keeps the geometry gives a value near 0
/// (docs/measurements.md).
double preparedVolumeError(double before, double after, const std::vector<Overlap>& overlaps);

}  // namespace aniso::cad
