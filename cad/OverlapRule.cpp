#include "cad/OverlapRule.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>

namespace aniso::cad {

int regionOwner(const std::vector<int>& parts, const std::vector<double>& partVolume) {
  int best = parts.front();
  for (const int p : parts) {
    const double vp = partVolume.at(static_cast<size_t>(p)), vb = partVolume.at(static_cast<size_t>(best));
    const bool tie = std::abs(vp - vb) <= kVolumeTieRel * std::max(std::abs(vp), std::abs(vb));
    if (tie ? p < best : vp < vb) best = p;
  }
  return best;
}

bool isFilm(double volume, double area, double diagonal) {
  return area > 0 && 2 * volume / area < kFilmThicknessRel * diagonal;
}

int regionOwner(const CommonRegion& r, const std::vector<double>& partVolume, double diagonal) {
  const int byVolume = regionOwner(r.parts, partVolume);
  if (r.width.size() != r.parts.size() || !isFilm(r.volume, r.area, diagonal)) return byVolume;
  const double widest = *std::max_element(r.width.begin(), r.width.end());
  const auto at = [&r](int part) { return r.width[static_cast<size_t>(std::find(r.parts.begin(), r.parts.end(), part) - r.parts.begin())]; };
  if (at(byVolume) >= kFilmWidthRatio * widest) return byVolume;
  std::vector<int> wide;  // the parts whose added faces are the widest; the volume rule among them
  for (size_t k = 0; k < r.parts.size(); ++k)
    if (r.width[k] == widest) wide.push_back(r.parts[k]);
  return regionOwner(wide, partVolume);
}

std::vector<Overlap> overlapPairs(const std::vector<CommonRegion>& regions) {
  struct Acc {
    double volume = 0, keptA = 0, keptB = 0;
    bool kept = false;
  };
  std::map<std::pair<int, int>, Acc> acc;
  for (const CommonRegion& r : regions)
    for (size_t i = 0; i < r.parts.size(); ++i)
      for (size_t j = i + 1; j < r.parts.size(); ++j) {
        const int a = std::min(r.parts[i], r.parts[j]), b = std::max(r.parts[i], r.parts[j]);
        Acc& x = acc[{a, b}];
        x.volume += r.volume;
        if (r.owner == a) x.keptA += r.volume;
        if (r.owner == b) x.keptB += r.volume;
        x.kept = x.kept || r.owner == a || r.owner == b;
      }
  std::vector<Overlap> out;
  for (const auto& [ab, x] : acc) {
    Overlap o;
    o.a = ab.first;
    o.b = ab.second;
    o.volume = x.volume;
    if (x.kept) o.assignedTo = x.keptA >= x.keptB ? o.a : o.b;
    out.push_back(o);
  }
  return out;
}

double overlapExcess(const std::vector<CommonRegion>& regions) {
  double v = 0;
  for (const CommonRegion& r : regions) v += static_cast<double>(r.parts.size() - 1) * r.volume;
  return v;
}

double preparedVolumeError(double before, double after, const std::vector<Overlap>& overlaps) {
  if (!(before > 0)) return 0;
  double merged = 0;
  for (const Overlap& o : overlaps)
    if (o.assignedTo != 0) merged += o.volume;
  return (after - (before - merged)) / before;
}

}  // namespace aniso::cad
