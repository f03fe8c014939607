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

Count predict(const std::vector<const FaceSizePrediction*>& faces, const std::vector<std::vector<int>>& solidFaces,
              const std::vector<double>& solidVolumes, double hFloor, std::vector<double>* perFace = nullptr) {
  Count c;
  std::vector<double> tri(faces.size(), 0.0);
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (faces[f]) c.triangles += tri[f] = faces[f]->triangles(hFloor);
  for (std::size_t s = 0; s < solidFaces.size(); ++s) {
    double t = 0, area = 0;
    for (int f : solidFaces[s]) {
      t += tri.at(static_cast<std::size_t>(f));
      if (faces[static_cast<std::size_t>(f)]) area += faces[static_cast<std::size_t>(f)]->area();
    }
    double tets = kTetsPerTriangle32 * std::pow(t, 1.5);
    const double volume = s < solidVolumes.size() ? solidVolumes[s] : 0.0;
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
  std::vector<double> asked;
  const Count c = predict(faces, solidFaces, solidVolumes, 0.0, &asked);
  b.triangles = c.triangles;
  b.tets = c.tets;
  b.predicted = b.predictedAfter = c.total();
  if (!(limit > 0) || b.predicted <= limit) return b;
  if (predict(faces, solidFaces, solidVolumes, hMax).total() > limit) {
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
    (predict(faces, solidFaces, solidVolumes, mid).total() > limit ? lo : hi) = mid;
  }
  b.floor = hi;
  std::vector<double> after;
  b.predictedAfter = predict(faces, solidFaces, solidVolumes, hi, &after).total();
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
