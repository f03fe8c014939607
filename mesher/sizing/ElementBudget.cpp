#include "mesher/sizing/ElementBudget.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace aniso {
namespace {

struct Count {
  double triangles = 0, tets = 0;
  double total() const { return triangles + tets; }
};

Count predict(const std::vector<const FaceSizePrediction*>& faces, const std::vector<std::vector<int>>& solidFaces,
              double hFloor, std::vector<double>* perFace = nullptr) {
  Count c;
  std::vector<double> tri(faces.size(), 0.0);
  for (std::size_t f = 0; f < faces.size(); ++f)
    if (faces[f]) c.triangles += tri[f] = faces[f]->triangles(hFloor);
  for (const std::vector<int>& solid : solidFaces) {
    double t = 0;
    for (int f : solid) t += tri.at(static_cast<std::size_t>(f));
    c.tets += kTetsPerTriangle32 * std::pow(t, 1.5);
  }
  if (perFace) *perFace = std::move(tri);
  return c;
}

}  // namespace

ElementBudget decideBudget(const std::vector<const FaceSizePrediction*>& faces,
                           const std::vector<std::vector<int>>& solidFaces, double limit, double hMax) {
  ElementBudget b;
  b.limit = limit;
  std::vector<double> asked;
  const Count c = predict(faces, solidFaces, 0.0, &asked);
  b.triangles = c.triangles;
  b.tets = c.tets;
  b.predicted = b.predictedAfter = c.total();
  if (!(limit > 0) || b.predicted <= limit) return b;
  if (predict(faces, solidFaces, hMax).total() > limit) {
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
    (predict(faces, solidFaces, mid).total() > limit ? lo : hi) = mid;
  }
  b.floor = hi;
  std::vector<double> after;
  b.predictedAfter = predict(faces, solidFaces, hi, &after).total();
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
