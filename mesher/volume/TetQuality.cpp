#include "mesher/volume/TetQuality.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "mesher/metric/MeanRatio.h"
#include "mesher/volume/improve/VertexTets.h"
#include "mesher/volume/refine/VertexTensors.h"

namespace aniso {
namespace {

constexpr double kRadToDeg = 57.29577951308232;

// Unit face normals as meshq.py builds them: faces (b,c,d), (a,c,d), (a,b,d), (a,b,c) with
// n = (y − x) × (z − x). For a positive tet n0 and n2 point outwards, n1 and n3 inwards.
void refereeNormals(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, Vec3 n[4]) {
  n[0] = (c - b).cross(d - b);
  n[1] = (c - a).cross(d - a);
  n[2] = (b - a).cross(d - a);
  n[3] = (b - a).cross(c - a);
  for (int i = 0; i < 4; ++i) n[i] *= 1.0 / std::max(n[i].norm(), 1e-300);
}

// Largest and smallest cosine of the 6 dihedral angles: −n_i·n_j with outward normals
// (`consistent`), or with meshq's normals as they are (`!consistent`).
void cosineRange(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, bool consistent, double& cmin,
                 double& cmax) {
  Vec3 n[4];
  refereeNormals(a, b, c, d, n);
  if (consistent) {
    const double s = (b - a).cross(c - a).dot(d - a) >= 0 ? 1.0 : -1.0;  // inverted: all flip
    n[0] *= s, n[1] *= -s, n[2] *= s, n[3] *= -s;
  }
  cmin = 1, cmax = -1;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const double cs = std::clamp(-n[i].dot(n[j]), -1.0, 1.0);
      cmin = std::min(cmin, cs);
      cmax = std::max(cmax, cs);
    }
}

}  // namespace

double tetMeanRatio(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) { return meanRatio(a, b, c, d); }

DihedralRange tetDihedralRange(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  double cmin, cmax;
  cosineRange(a, b, c, d, true, cmin, cmax);
  return {std::acos(cmax) * kRadToDeg, std::acos(cmin) * kRadToDeg};
}

double tetMinDihedral(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  double cmin, cmax;
  cosineRange(a, b, c, d, true, cmin, cmax);
  return std::acos(cmax) * kRadToDeg;
}

double tetMinDihedral(const del3d::TetMesh& mesh, del3d::TetId t) {
  const std::uint32_t* v = mesh.tetVertices(t);
  return tetMinDihedral(mesh.point(del3d::VertexId(v[0])), mesh.point(del3d::VertexId(v[1])),
                        mesh.point(del3d::VertexId(v[2])), mesh.point(del3d::VertexId(v[3])));
}

bool dihedralCosineOutside(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, double cosAbove,
                           double cosBelow) {
  const Vec3 n[4] = {(c - b).cross(d - b), (c - a).cross(d - a), (b - a).cross(d - a), (b - a).cross(c - a)};
  const double sq[4] = {n[0].squaredNorm(), n[1].squaredNorm(), n[2].squaredNorm(), n[3].squaredNorm()};
  const double above2 = cosAbove * cosAbove, below2 = cosBelow * cosBelow;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      // the true cosine is x / (|n_i| |n_j|) with x = −n_i·n_j for pairs of equal parity
      // and +n_i·n_j for the others (cosines() below), whatever the volume's sign; it is
      // above cosAbove ≥ 0 when x > 0 and x² > cosAbove² |n_i|² |n_j|², below cosBelow ≤ 0
      // when x < 0 and x² > cosBelow² |n_i|² |n_j|² (a zero normal: x = 0, neither)
      const double x = ((i ^ j) & 1) ? n[i].dot(n[j]) : -n[i].dot(n[j]);
      if (x * x > (x > 0 ? above2 : below2) * (sq[i] * sq[j])) return true;
    }
  return false;
}

double refereeMinDihedral(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  double cmin, cmax;
  cosineRange(a, b, c, d, false, cmin, cmax);
  return std::acos(cmax) * kRadToDeg;
}

void TetQualitySummary::merge(const TetQualitySummary& o) {
  tets += o.tets;
  inverted += o.inverted;
  volume += o.volume;
  meanRatio.merge(o.meanRatio);
  minDihedral = std::min(minDihedral, o.minDihedral);
  maxDihedral = std::max(maxDihedral, o.maxDihedral);
  belowDihedral += o.belowDihedral;
  refereeMinDihedral = std::min(refereeMinDihedral, o.refereeMinDihedral);
  etaM.merge(o.etaM);
  muM.merge(o.muM);
  muMUser.merge(o.muMUser);
}

namespace {

/// Largest (referee's and true) and smallest (true) cosine of the dihedral angles of one
/// tet from one set of unit normals (refereeNormals): meshq's cosine of pair (i, j) is
/// −n_i·n_j; with outward normals (n0, n2 flipped relative to n1, n3 for either sign of
/// the volume) the pairs of equal parity, (0, 2) and (1, 3), keep that sign and the four
/// others change it.
void cosines(const Vec3 n[4], double& trueMin, double& trueMax, double& refereeMax) {
  trueMin = 1, trueMax = -1, refereeMax = -1;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const double raw = std::clamp(-n[i].dot(n[j]), -1.0, 1.0);
      const double c = ((i ^ j) & 1) ? -raw : raw;
      trueMin = std::min(trueMin, c);
      trueMax = std::max(trueMax, c);
      refereeMax = std::max(refereeMax, raw);
    }
}

}  // namespace

namespace {

/// The per-vertex tensors the report measures with, as refine3d::VertexTensors keeps them:
/// an isotropic tensor is s·I (its scale), another the full matrix. Queried from the
/// control space, or read from the improvement's VertexMetrics (same values: both store
/// cs.getMetric at the vertex's position and reduce s·I within isotropicScale's tolerance
/// to its scale).
class ReportTensors {
 public:
  ReportTensors(const del3d::TetMesh& mesh, const ControlSpace3d& cs, const improve3d::VertexMetrics* metrics)
      : metrics_(metrics) {
    if (!metrics) {
      queried_ = std::make_unique<refine3d::VertexTensors>(mesh, cs);
      return;
    }
    scale_.resize(mesh.numVertices(), 0.0);
    for (std::uint32_t v = 0; v < scale_.size(); ++v)
      if (metrics->isIsotropic(del3d::VertexId(v))) scale_[v] = isotropicScale(metrics->at(del3d::VertexId(v)));
  }
  double scale(del3d::VertexId v) const { return queried_ ? queried_->scale(v) : scale_[v.index]; }
  Mat3 at(del3d::VertexId v) const {
    if (queried_) return queried_->at(v);
    const double s = scale_[v.index];
    return s > 0 ? Mat3(s * Mat3::Identity()) : metrics_->at(v);
  }
  /// Every vertex isotropic: η_M = η for every tet.
  bool allIsotropic(std::size_t numVertices) const {
    for (std::uint32_t v = 0; v < numVertices; ++v)
      if (!(scale(del3d::VertexId(v)) > 0)) return false;
    return true;
  }
  bool tetIsotropic(const std::uint32_t* v) const {
    return scale(del3d::VertexId(v[0])) > 0 && scale(del3d::VertexId(v[1])) > 0 && scale(del3d::VertexId(v[2])) > 0 &&
           scale(del3d::VertexId(v[3])) > 0;
  }
  Mat3 tetMetric(const std::uint32_t* v) const {
    return 0.25 * (at(del3d::VertexId(v[0])) + at(del3d::VertexId(v[1])) + at(del3d::VertexId(v[2])) +
                   at(del3d::VertexId(v[3])));
  }

 private:
  const improve3d::VertexMetrics* metrics_;
  std::unique_ptr<refine3d::VertexTensors> queried_;
  std::vector<double> scale_;
};

}  // namespace

namespace {

/// Values gathered for QualityStats::addAll in blocks (one division per block).
class StatsBuffer {
 public:
  explicit StatsBuffer(QualityStats& to) : to_(to) {}
  ~StatsBuffer() { flush(); }
  StatsBuffer(const StatsBuffer&) = delete;
  StatsBuffer& operator=(const StatsBuffer&) = delete;
  void add(double v) {
    buf_[n_++] = v;
    if (n_ == buf_.size()) flush();
  }
  void flush() {
    to_.addAll(std::span<const double>(buf_.data(), n_));
    n_ = 0;
  }

 private:
  QualityStats& to_;
  std::array<double, 512> buf_;
  std::size_t n_ = 0;
};

}  // namespace

// One pass: the angles are compared as cosines (acos is decreasing), converted once at the
// end. The metric of a tet is the mean of its vertices' tensors and that of an edge the mean
// of its ends' (as the refinement's edge check and the improvement measure them): one
// control-space query per vertex instead of one per tet and one per edge (none for a
// boundary node in the user's metric: its length factor is 1). The statistics are
// gathered in blocks (StatsBuffer).
void accumulateTetQuality(const SolidTetMesh& s, const ControlSpace3d* cs, TetQualitySummary& out,
                          const VolumeMetricSpace* volume, const improve3d::VertexMetrics* metrics) {
  const del3d::TetMesh& mesh = s.mesh;
  const double cosSliver = std::cos(kSliverDihedralDeg / kRadToDeg);
  double cmin = 1, cmax = -1, refereeCmax = -1;
  QualityStats etaStats;  // this call's η (merged into out.meanRatio, and out.etaM when η_M = η)
  std::unique_ptr<ReportTensors> vt;
  if (cs) vt = std::make_unique<ReportTensors>(mesh, *cs, metrics);
  const bool etaMIsEta = vt && vt->allIsotropic(mesh.numVertices());
  {
    StatsBuffer eta(etaStats), etaM(out.etaM);
    for (std::uint32_t k = 0; k < mesh.tetSlots(); ++k) {
      const del3d::TetId t(k);
      if (!mesh.isAlive(t)) continue;
      const std::uint32_t* tv = mesh.tetVertices(t);
      const Vec3 a = mesh.point(del3d::VertexId(tv[0])), b = mesh.point(del3d::VertexId(tv[1]));
      const Vec3 c = mesh.point(del3d::VertexId(tv[2])), d = mesh.point(del3d::VertexId(tv[3]));
      const double vol = (b - a).cross(c - a).dot(d - a) / 6.0;
      ++out.tets;
      out.volume += vol;
      if (vol <= 0) ++out.inverted;
      const double etaK = meanRatio(a, b, c, d);
      eta.add(etaK);
      Vec3 n[4];
      refereeNormals(a, b, c, d, n);
      double lo, hi, ref;
      cosines(n, lo, hi, ref);
      cmin = std::min(cmin, lo);
      cmax = std::max(cmax, hi);
      refereeCmax = std::max(refereeCmax, ref);
      if (hi > cosSliver) ++out.belowDihedral;
      if (!vt || etaMIsEta) continue;
      if (vt->tetIsotropic(tv)) {
        etaM.add(etaK);  // a mean of s·I tensors is isotropic: η_M = η
      } else {
        const Mat3 m = vt->tetMetric(tv);
        etaM.add(meanRatio(Vec3(m * a), Vec3(m * b), Vec3(m * c), Vec3(m * d)));
      }
    }
  }
  out.meanRatio.merge(etaStats);
  if (etaMIsEta) out.etaM.merge(etaStats);
  if (out.tets > 0) {
    out.minDihedral = std::min(out.minDihedral, std::acos(cmax) * kRadToDeg);
    out.maxDihedral = std::max(out.maxDihedral, std::acos(cmin) * kRadToDeg);
    out.refereeMinDihedral = std::min(out.refereeMinDihedral, std::acos(refereeCmax) * kRadToDeg);
  }
  if (!vt) return;
  // μ_M: each edge once, from the tets around its lower-index end: a vertex -> tets
  // incidence (compressed rows, 4 entries per tet) read row by row, the neighbours already
  // measured marked by a stamp (no star walks, no sorting).
  const std::size_t nv = mesh.numVertices();
  const improve3d::VertexTets incidence(mesh);
  std::vector<double> toUser(volume ? nv : 0, 1.0);  // per vertex: M = toUser · M_v
  // The tensors held are M_v's when volume is cs (as the volume mesher calls it).
  const bool heldAreMv = volume && static_cast<const ControlSpace3d*>(volume) == cs;
  for (std::size_t v = 0; v < toUser.size(); ++v) {
    const del3d::VertexId id(static_cast<std::uint32_t>(v));
    // At a surface node M_v is M (VolumeMetricSpace::onBoundary); elsewhere the factor from
    // the held M_v (VolumeMetricSpace::lengthFactorFrom: no query of M).
    if (s.isFixed(id) && volume->onBoundary(mesh.point(id))) continue;
    toUser[v] = heldAreMv ? volume->lengthFactorFrom(mesh.point(id), vt->at(id)) : volume->lengthFactorAt(mesh.point(id));
  }
  std::vector<std::uint32_t> seen(nv, del3d::kNone);
  StatsBuffer muM(out.muM), muMUser(out.muMUser);
  for (std::uint32_t v = 0; v < nv; ++v) {
    const Vec3 p = mesh.point(del3d::VertexId(v));
    for (const std::uint32_t t : incidence.of(del3d::VertexId(v))) {
      const std::uint32_t* tv = mesh.tetVertices(del3d::TetId(t));
      for (int i = 0; i < 4; ++i) {
        const std::uint32_t w = tv[i];
        if (w <= v || seen[w] == v) continue;
        seen[w] = v;
        const Vec3 dq = mesh.point(del3d::VertexId(w)) - p;
        const double sv = vt->scale(del3d::VertexId(v)), sw = vt->scale(del3d::VertexId(w));
        const double fv = volume ? toUser[v] : 1.0, fw = volume ? toUser[w] : 1.0;
        if (sv > 0 && sw > 0) {
          const double l = dq.norm();
          muM.add(0.5 * (sv + sw) * l);
          muMUser.add(0.5 * (fv * sv + fw * sw) * l);
        } else {
          const Mat3 tv = vt->at(del3d::VertexId(v)), tw = vt->at(del3d::VertexId(w));
          muM.add((0.5 * (tv + tw) * dq).norm());
          muMUser.add((0.5 * (fv * tv + fw * tw) * dq).norm());
        }
      }
    }
  }
}

}  // namespace aniso
