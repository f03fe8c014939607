#pragma once
// Which part keeps a region common to overlapping parts (--overlaps merge), and the pairs
// reported for it. No OCCT: the rule is unit-tested on plain numbers.
//
// Rule: a common region is meshed once, in the part of SMALLEST volume (volumes as read,
// before fragmenting) among the parts that contain it; volumes equal within kVolumeTieRel
// (relative) are a tie, won by the part first in the file (smaller id). So a screw modelled
// inside its threaded hole, a pin pressed into a housing or a coil inside its moulded body
// stays whole, and the larger part loses the common region (it gets a cavity there).
#include <vector>

#include "cad/CadModel.h"

namespace aniso::cad {

/// Volumes closer than this, relative to the larger, are equal for the rule.
inline constexpr double kVolumeTieRel = 1e-6;

/// A solid of the general fuse that is an image of several parts.
struct CommonRegion {
  std::vector<int> parts;  ///< 1-based ids of the parts containing it, ascending, size >= 2
  double volume = 0;
  int owner = 0;           ///< the part that keeps it (regionOwner), 0 until assigned
};

/// The part of `parts` (1-based ids, non-empty) that keeps their common region;
/// partVolume[id] is the volume of part id (index 0 unused).
int regionOwner(const std::vector<int>& parts, const std::vector<double>& partVolume);

/// One entry per pair of parts with a common region, sorted by (a, b): volume = the sum of
/// the regions containing both; assignedTo = the one of a, b that keeps most of that volume
/// (0 when every such region went to a third part or is unassigned). Names are left empty.
std::vector<Overlap> overlapPairs(const std::vector<CommonRegion>& regions);

/// The volume counted more than once by the parts: sum over regions of (parts - 1) × volume
/// (= the parts' total volume minus the union's).
double overlapExcess(const std::vector<CommonRegion>& regions);

}  // namespace aniso::cad
