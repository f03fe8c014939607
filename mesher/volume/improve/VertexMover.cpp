#include "mesher/volume/improve/VertexMover.h"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>

#include "mesher/predicates/Predicates.h"
#include "mesher/volume/TetQuality.h"
#include "mesher/volume/improve/TetStar.h"

namespace aniso::improve3d {
namespace {
/// Perturbation radii of relocate(), relative to the shortest edge of the star.
constexpr double kPerturbRadii[2] = {0.15, 0.05};
/// relocate(v, angles = true) keeps the star's worst η_M³ above this fraction of its value.
constexpr double kAngleMoveScoreKeep = 0.5;
/// relocate(v, true): after the fixed candidates, a compass search (26 directions) from the
/// best position, its radius doubled after a gain (at most the shortest edge) and halved
/// otherwise, for at most this many steps or until it falls below kAngleSearchMinRadius ×
/// the shortest edge. Measured on a real assembly (GNSS antenna, a sliver on a curved face
/// at an interface): the fixed candidates left 1.9° (a random search of that star found
/// 3.9° 0.01 mm away); with this search the whole mesh's smallest angle became 4.98°.
constexpr int kAngleSearchSteps = 24;
constexpr double kAngleSearchMinRadius = 1e-3;
}  // namespace

void VertexMover::loadStar(del3d::VertexId v) {
  if (incidence_) {
    star_.clear();
    for (const std::uint32_t t : incidence_->of(v)) star_.push_back(del3d::TetId(t));
  } else {
    vertexStar(s_.mesh, v, star_);
  }
  nbrs_.clear();
  if (seen_.size() < s_.mesh.numVertices()) seen_.resize(s_.mesh.numVertices(), 0);
  if (++stamp_ == 0) {
    std::fill(seen_.begin(), seen_.end(), 0u);
    stamp_ = 1;
  }
  seen_[v.index] = stamp_;
  for (const del3d::TetId t : star_)
    for (int i = 0; i < 4; ++i) {
      const std::uint32_t w = s_.mesh.tetVertices(t)[i];
      if (seen_[w] != stamp_) seen_[w] = stamp_, nbrs_.push_back(w);
    }
}

bool VertexMover::legal(del3d::VertexId v, const Vec3& p, bool trialScored) const {
  const double xyz[3] = {p.x(), p.y(), p.z()};
  for (std::size_t k = 0; k < star_.size(); ++k) {
    const std::uint32_t* tv = s_.mesh.tetVertices(star_[k]);
    if (trialScored && vm_.certifiesOrientation(tv, trial_[k])) continue;
    const double* c[4];
    for (int i = 0; i < 4; ++i) c[i] = tv[i] == v.index ? xyz : s_.mesh.coords(del3d::VertexId(tv[i]));
    if (predicates::orient3d(c[0], c[1], c[2], c[3]) <= 0) return false;
  }
  return true;
}

bool VertexMover::quality(del3d::VertexId v, const Vec3& p, double& worst, double& mean, double rejectBelow) {
  worst = 1e300;
  double sum = 0;
  trial_.resize(star_.size());
  for (std::size_t k = 0; k < star_.size(); ++k) {
    const double e = trial_[k] = vm_.scoreWith(s_.mesh.tetVertices(star_[k]), v.index, p);
    if (e < rejectBelow) return false;
    worst = std::min(worst, e);
    sum += e;
  }
  mean = star_.empty() ? 0 : sum / static_cast<double>(star_.size());
  return true;
}

Vec3 VertexMover::laplaceTarget(del3d::VertexId v, double lowGradation) const {
  const Vec3 q = s_.mesh.point(v);
  const Mat3& mq = vm_.at(v);
  // the gradation max_w |M_w − M_q| / |M_q| against lowGradation, on squares
  const double limit = lowGradation * lowGradation * mq.squaredNorm();
  bool graded = lowGradation < 0;
  Vec3 mean = Vec3::Zero();
  for (const std::uint32_t w : nbrs_) {
    mean += s_.mesh.point(del3d::VertexId(w));
    if (!graded) graded = (vm_.at(del3d::VertexId(w)) - mq).squaredNorm() > limit;
  }
  mean /= static_cast<double>(nbrs_.size());
  if (!graded) return mean;
  // eq. 4.3: x^M = mean of M_i (P_i − Q), M_i the mid-edge tensor scaled to det M_Q.
  const double detQ = mq.determinant();
  Vec3 xm = Vec3::Zero();
  for (const std::uint32_t w : nbrs_) {
    Mat3 mi = 0.5 * (mq + vm_.at(del3d::VertexId(w)));
    mi *= std::cbrt(detQ / mi.determinant());
    xm += mi * (s_.mesh.point(del3d::VertexId(w)) - q);
  }
  xm /= static_cast<double>(nbrs_.size());
  return q + mq.inverse() * xm;
}

void VertexMover::move(del3d::VertexId v, const Vec3& p) {
  s_.mesh.movePoint(v, p);
  vm_.refresh(v);
}

bool VertexMover::smooth(del3d::VertexId v, double lowGradation, double qualityFloor, bool ascent) {
  if (s_.isFixed(v) || !s_.mesh.vertexTet(v).valid()) return false;
  loadStar(v);
  if (nbrs_.empty()) return false;
  const Vec3 q = s_.mesh.point(v);
  const Vec3 target = laplaceTarget(v, lowGradation);
  double w0, m0;
  if (scores_) {
    w0 = 1e300;
    double sum = 0;
    for (const del3d::TetId t : star_) {
      const double e = (*scores_)[t];
      w0 = std::min(w0, e);
      sum += e;
    }
    m0 = sum / static_cast<double>(star_.size());
  } else {
    quality(v, q, w0, m0);
  }
  const double floor = qualityFloor * qualityFloor * qualityFloor;  // scores are η³
  // a trial tet below this already rejects the move (w1 ≤ w0, resp. w1 < floor)
  const double rejectBelow = w0 < floor ? std::nextafter(w0, 1e300) : floor;
  // the ascent step (q when it finds none), then the Laplace move and its half
  const std::array<Vec3, 3> candidates = {ascent ? ascentStep(v) : q, target, q + 0.5 * (target - q)};
  for (const Vec3& p : candidates) {
    if (p == q) continue;
    double w1, m1;
    // floating point first: most rejected moves need no exact test
    if (!quality(v, p, w1, m1, rejectBelow)) continue;
    const bool better = w0 < floor ? w1 > w0 : (w1 >= floor && m1 >= m0);
    if (better && legal(v, p, true)) {
      const Mat3 before = vm_.at(v);
      const bool wasIsotropic = vm_.isIsotropic(v);
      move(v, p);
      if (scores_) {
        // A trial score holds when the tet's metric did not change: v's tensor is the same,
        // or the tet is isotropic now and v was before (its score is Euclidean, whatever the
        // scales).
        const bool same = vm_.at(v) == before;
        for (std::size_t k = 0; k < star_.size(); ++k) {
          if (same || (wasIsotropic && vm_.isIsotropic(s_.mesh.tetVertices(star_[k]))))
            scores_->set(star_[k], trial_[k]);
          else
            scores_->update(star_[k]);
        }
      }
      return true;
    }
  }
  return false;
}

double VertexMover::meanEta(del3d::VertexId v, const Vec3& p) const {
  double sum = 0;
  for (const del3d::TetId t : star_) {
    const double e = vm_.scoreWith(s_.mesh.tetVertices(t), v.index, p);
    if (!(e > 0)) return -1;  // inverted or flat: never better
    sum += std::cbrt(e);
  }
  return sum / static_cast<double>(star_.size());
}

// One step of steepest ascent of the (loaded) star's mean η_M: the gradient summed over the
// star (VertexMetrics::etaGradient), then a backtracking line search from kAscentFirstStep ·
// L (L the mean distance to the neighbours), halving at most kAscentHalvings times.
Vec3 VertexMover::ascentStep(del3d::VertexId v) const {
  const Vec3 q = s_.mesh.point(v);
  double L = 0;
  for (const std::uint32_t w : nbrs_) L += (s_.mesh.point(del3d::VertexId(w)) - q).norm();
  L /= static_cast<double>(nbrs_.size());
  const double f0 = meanEta(v, q);
  if (!(L > 0) || !(f0 > 0)) return q;
  Vec3 g = Vec3::Zero();
  for (const del3d::TetId t : star_) {
    Vec3 gt;
    vm_.etaGradient(s_.mesh.tetVertices(t), v.index, gt);
    g += gt;
  }
  if (!(g.norm() > 0)) return q;
  const Vec3 dir = g.normalized();
  double step = kAscentFirstStep * L;
  for (int k = 0; k <= kAscentHalvings; ++k, step *= 0.5) {
    const Vec3 p = q + step * dir;
    if (meanEta(v, p) > f0) return p;
  }
  return q;
}

// The position of v that makes the worst tet of its (loaded) star regular in that tet's
// metric: the apex over the opposite face, on v's side.
Vec3 VertexMover::worstApex(del3d::VertexId v) const {
  del3d::TetId worst;
  double w = 1e300;
  for (const del3d::TetId t : star_) {
    const double e = vm_.score(t);
    if (e < w) w = e, worst = t;
  }
  const std::uint32_t* tv = s_.mesh.tetVertices(worst);
  const int iv = s_.mesh.localIndex(worst, v);
  const Mat3 m = vm_.tetMetric(tv);
  const Vec3 a = m * s_.mesh.point(del3d::VertexId(tv[del3d::kFaceVertex[iv][0]]));
  const Vec3 b = m * s_.mesh.point(del3d::VertexId(tv[del3d::kFaceVertex[iv][1]]));
  const Vec3 c = m * s_.mesh.point(del3d::VertexId(tv[del3d::kFaceVertex[iv][2]]));
  Vec3 n = (b - a).cross(c - a).normalized();
  if (n.dot(m * s_.mesh.point(v) - a) < 0) n = -n;  // v's side
  const double len = ((b - a).norm() + (c - b).norm() + (a - c).norm()) / 3;
  return m.inverse() * ((a + b + c) / 3 + std::sqrt(2.0 / 3.0) * len * n);
}

double VertexMover::angleMeasure(del3d::VertexId v, const Vec3& p, double stopAtOrBelow) const {
  double worst = 180;
  for (const del3d::TetId t : star_) {
    const std::uint32_t* tv = s_.mesh.tetVertices(t);
    const Mat3 m = vm_.tetMetric(tv);
    Vec3 q[4];
    for (int i = 0; i < 4; ++i) q[i] = m * (tv[i] == v.index ? p : s_.mesh.point(del3d::VertexId(tv[i])));
    const DihedralRange r = tetDihedralRange(q[0], q[1], q[2], q[3]);
    worst = std::min({worst, r.minDeg, 180 - r.maxDeg});
    if (worst <= stopAtOrBelow) break;
  }
  return worst;
}

bool VertexMover::relocate(del3d::VertexId v, bool angles) {
  if (s_.isFixed(v) || !s_.mesh.vertexTet(v).valid()) return false;
  loadStar(v);
  if (nbrs_.empty()) return false;
  const Vec3 q = s_.mesh.point(v);
  double worst0, mean;
  quality(v, q, worst0, mean);
  // The star's poorest tets first (stable: equal scores keep their order): a candidate
  // position is rejected at its first tet not above the best so far, soonest this way.
  order_.resize(star_.size());
  for (std::size_t k = 0; k < order_.size(); ++k) order_[k] = static_cast<std::uint32_t>(k);
  std::stable_sort(order_.begin(), order_.end(), [&](std::uint32_t x, std::uint32_t y) { return trial_[x] < trial_[y]; });
  sorted_.resize(star_.size());
  for (std::size_t k = 0; k < order_.size(); ++k) sorted_[k] = star_[order_[k]];
  star_.swap(sorted_);
  double best = angles ? angleMeasure(v, q, -1e300) : worst0;
  double shortest = 1e300;
  for (const std::uint32_t w : nbrs_) shortest = std::min(shortest, (s_.mesh.point(del3d::VertexId(w)) - q).norm());
  Vec3 bestP = q;
  // the angles may not cost more than half the star's worst η_M³
  const double keep = std::nextafter(kAngleMoveScoreKeep * worst0, 1e300);
  auto consider = [&](const Vec3& p) {
    double w, m;
    if (!quality(v, p, w, m, angles ? keep : std::nextafter(best, 1e300))) return;  // w ≤ the bound
    if (angles) w = angleMeasure(v, p, best);
    if (w > best && legal(v, p, true)) best = w, bestP = p;
  };
  consider(laplaceTarget(v, -1.0));
  const Vec3 apex = worstApex(v);
  consider(apex);
  consider(0.5 * (q + apex));
  // the 26 directions of the cube around c, at distance `radius`
  auto around = [&](const Vec3 c, double radius) {  // c by value: consider() moves bestP
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          if (dx == 0 && dy == 0 && dz == 0) continue;
          const Vec3 d(dx, dy, dz);
          consider(c + (radius / d.norm()) * d);
        }
  };
  for (const double r : kPerturbRadii) around(q, r * shortest);
  if (angles) {
    double r = kPerturbRadii[0] * shortest;
    for (int step = 0; step < kAngleSearchSteps && r > kAngleSearchMinRadius * shortest; ++step) {
      const double before = best;
      around(bestP, r);
      r = best > before ? std::min(2 * r, shortest) : 0.5 * r;
    }
  }
  if (bestP == q) return false;
  move(v, bestP);
  return true;
}

}  // namespace aniso::improve3d
