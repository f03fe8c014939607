#include "mesher/sizing/ElementBudget.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mesher/surface/face/FaceMetric.h"

namespace aniso {
namespace {

struct Count {
  double triangles = 0, tets = 0;
  double total() const { return triangles + tets; }
};

/// The solids' volumes and boundary areas (the faces' predictions), which no floor changes.
struct Solids {
  const std::vector<std::vector<int>>& faces;
  const std::vector<double>& volumes;
  std::vector<double> areas;
};

Solids measureSolids(const std::vector<const FaceSizePrediction*>& faces,
                     const std::vector<std::vector<int>>& solidFaces, const std::vector<double>& solidVolumes) {
  Solids out{solidFaces, solidVolumes, std::vector<double>(solidFaces.size(), 0.0)};
  for (std::size_t s = 0; s < solidFaces.size(); ++s)
    for (int f : solidFaces[s])
      if (faces.at(static_cast<std::size_t>(f))) out.areas[s] += faces[static_cast<std::size_t>(f)]->area();
  return out;
}

Count predict(const std::vector<const FaceSizePrediction*>& faces, const Solids& solids, double hFloor,
              std::vector<double>* perFace = nullptr) {
  Count c;
  std::vector<double> tri(faces.size(), 0.0);
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (faces[f]) c.triangles += tri[f] = faces[f]->triangles(hFloor);
  for (std::size_t s = 0; s < solids.faces.size(); ++s) {
    double t = 0;
    for (int f : solids.faces[s]) t += tri.at(static_cast<std::size_t>(f));
    const double area = solids.areas[s];
    double tets = kTetsPerTriangle32 * std::pow(t, 1.5);
    const double volume = s < solids.volumes.size() ? solids.volumes[s] : 0.0;
    if (volume > 0 && area > 0 && t > 0) {
      const double h = std::sqrt(area / (face::kIdealTriangleArea * t));  // the boundary's mean size
      tets = std::min(tets, std::max(t, kTetsPerVolume * volume / (h * h * h)));
    }
    c.tets += tets;
  }
  if (perFace) *perFace = std::move(tri);
  return c;
}

}  // namespace

ElementBudget decideBudget(const std::vector<const FaceSizePrediction*>& faces,
                           const std::vector<std::vector<int>>& solidFaces, double limit, double hMax,
                           const std::vector<double>& solidVolumes) {
  ElementBudget b;
  b.limit = limit;
  const Solids solids = measureSolids(faces, solidFaces, solidVolumes);
  std::vector<double> asked;
  const Count c = predict(faces, solids, 0.0, &asked);
  b.triangles = c.triangles;
  b.tets = c.tets;
  b.predicted = b.predictedAfter = c.total();
  if (!(limit > 0) || b.predicted <= limit) return b;
  if (predict(faces, solids, hMax).total() > limit) {
    b.fits = false;
    return b;
  }
  double lo = std::numeric_limits<double>::infinity();
  for (const FaceSizePrediction* f : faces)
    if (f) lo = std::min(lo, f->smallestLength());
  if (!(lo > 0 && lo < hMax)) lo = hMax * 1e-9;
  double hi = hMax;  // fits; lo does not (it changes nothing)
  for (int i = 0; i < kFloorBisections && hi > lo * (1 + 1e-6); ++i) {
    const double mid = std::sqrt(lo * hi);
    (predict(faces, solids, mid).total() > limit ? lo : hi) = mid;
  }
  b.floor = hi;
  std::vector<double> after;
  b.predictedAfter = predict(faces, solids, hi, &after).total();
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (faces[f] && after[f] < (1 - kCoarsenedShare) * asked[f])
      b.coarsened.push_back({static_cast<int>(f), asked[f], after[f]});
  std::stable_sort(b.coarsened.begin(), b.coarsened.end(), [](const BudgetCoarsening& x, const BudgetCoarsening& y) {
    return x.before - x.after > y.before - y.after;
  });
  return b;
}

double defaultElementBudget(double availableBytes, int dim) {
  return std::max(availableBytes, 0.0) / (dim == 3 ? kBytesPerTet : kBytesPerTriangle);
}

}  // namespace aniso
