#include "mesher/volume/VolumeRefinement.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <array>
#include <cmath>

#include "mesher/delaunay3d/Inserter.h"
#include "mesher/delaunay3d/Locate.h"
#include "mesher/delaunay3d/SpatialSort.h"
#include "mesher/volume/refine/BoundaryEdge.h"
#include "mesher/volume/refine/RefineQueue.h"
#include "mesher/volume/refine/TetMetricGeometry.h"
#include "mesher/volume/refine/VertexTensors.h"

namespace aniso {
namespace {

using del3d::TetId;
using del3d::VertexId;

constexpr int kEdges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
/// The edge check (5.5.1) first measures the edges in M_K; only when one is longer than
/// edgeLengthMax / kEdgePrefilter there are the midpoint metrics queried (gradation γ_M ≤ 4
/// changes a length by far less than this factor across one element).
constexpr double kEdgePrefilter = 1.3;
/// A CCS point in an anisotropic M_K is cancelled when a vertex near it lies inside K's
/// circumsphere in M_K by more than this fraction of the radius (see the header).
constexpr double kCircumsphereMargin = 0.99;
/// Floor of the predicted count in the vertex budget (small or coarse solids).
constexpr double kMinBudgetTets = 1e5;
/// Arrays reserved for this multiple of the eq. 6.2 prediction, which under-estimates (unit
/// cube at h = 0.02: 1.07 M predicted, 1.40 M tets after refinement). Reserved pages that
/// are never written cost no resident memory.
constexpr double kReserveFactor = 1.5;
/// Cap of that reservation (64 M tets, 2.2 GB): a larger mesh grows its arrays as it goes,
/// so that a wild prediction never asks for an allocation beyond the machine.
constexpr double kMaxReserveTets = 67108864.0;
/// Tets per vertex of a unit mesh (5.7-5.8 measured), for the vertex arrays.
constexpr double kTetsPerVertex = 5.5;
/// Batch entries whose memory is requested this many entries ahead.
constexpr std::size_t kPrefetchAhead = 8;
/// Volume of the unit regular tet, V_M(K_I) of eq. 6.2.
constexpr double kIdealVolume = 0.11785113019775793;  // 1 / (6√2)

struct TetPoints {
  std::array<Vec3, 4> p;
  Vec3 centroid() const { return 0.25 * (p[0] + p[1] + p[2] + p[3]); }
};

TetPoints pointsOf(const del3d::TetMesh& mesh, TetId t) {
  TetPoints tp;
  for (int i = 0; i < 4; ++i) tp.p[i] = mesh.point(mesh.vertex(t, i));
  return tp;
}

class Refiner {
 public:
  Refiner(SolidTetMesh& s, const ControlSpace3d& cs, const VolumeRefineOptions& o)
      : s_(s), mesh_(s.mesh), cs_(cs), o_(o), inserter_(s.mesh), vt_(s.mesh, cs), heap_(o.qualityThreshold) {}

  VolumeRefineStats run();
  refine3d::VertexTensorTable releaseTensors() { return vt_.release(); }

 private:
  double evaluate(TetId t);
  double evaluateIsotropic(TetId t, const std::uint32_t* tv, double scale) const;
  void enqueue(TetId t);
  bool refine(TetId k, double q);
  void process(const refine3d::RefineQueue::Entry& e);
  bool longestInnerEdgeMidpoint(TetId k, const Mat3& m, const TetPoints& tp, Vec3& out) const;
  enum class Outcome { Inserted, Outside, Close, Metric, Refused };
  /// sphere: for a CCS point in an anisotropic M_K, M_K and K's circumradius in it.
  struct Sphere {
    const Mat3* metric = nullptr;
    double radius = 0;
  };
  Outcome tryInsert(const Vec3& p, TetId k, bool mle, const Sphere& sphere);
  bool nearHull(const Vec3& p, const Metric3d& m, TetId c) const;
  bool insideSphere(const Vec3& p, const Sphere& sphere, TetId c) const;

  SolidTetMesh& s_;
  del3d::TetMesh& mesh_;
  const ControlSpace3d& cs_;
  const VolumeRefineOptions& o_;
  del3d::Inserter inserter_;
  refine3d::VertexTensors vt_;
  refine3d::RefineQueue heap_;
  std::vector<std::uint8_t> postponed_;
  std::uint32_t rng_ = 0x9E3779B9u;
  VolumeRefineStats st_;
  std::size_t sinceProgress_ = 0;
  std::size_t maxVertices_ = 0;

  void reserveFor(double predictedTets);
};

void Refiner::reserveFor(double predictedTets) {
  const double tets = std::min(kReserveFactor * predictedTets, kMaxReserveTets);
  if (!(tets > static_cast<double>(mesh_.tetSlots()))) return;
  const std::size_t nt = static_cast<std::size_t>(tets);
  mesh_.reserve(mesh_.numVertices() + static_cast<std::size_t>(tets / kTetsPerVertex), nt);
  // The per-slot arrays grow one slot at a time within this room (pages touched as used).
  heap_.reserve(nt);
  postponed_.reserve(nt);
}

double Refiner::evaluate(TetId t) {
  ++st_.evaluated;
  const std::uint32_t* tv = mesh_.tetVertices(t);
  double scale;
  if (vt_.tetLengthScale(tv, scale)) return evaluateIsotropic(t, tv, scale);
  const TetPoints tp = pointsOf(mesh_, t);
  const Mat3 m = vt_.tetLengthMetric(tv);
  double q = refine3d::metricSphereQuality(m, tp.p[0], tp.p[1], tp.p[2], tp.p[3]);
  if (q < o_.qualityThreshold) return q;
  // 5.5.1: a tet of good q with a too long edge is refined all the same.
  for (const auto& e : kEdges) {
    // An edge between two surface nodes may be a boundary edge, which no inner node can
    // shorten: such edges are left to q (their tets' circumspheres).
    if (s_.isFixed(VertexId(tv[e[0]])) && s_.isFixed(VertexId(tv[e[1]]))) continue;
    const Vec3 d = tp.p[e[1]] - tp.p[e[0]];
    if ((m * d).norm() * kEdgePrefilter <= o_.edgeLengthMax) continue;
    const Mat3 mid = vt_.edgeLengthMetric(VertexId(tv[e[0]]), VertexId(tv[e[1]]));
    if ((mid * d).norm() > o_.edgeLengthMax) return 0.95 * o_.qualityThreshold;
  }
  return q;
}

// evaluate() for a tet whose vertices are all isotropic: its metric is scale·I, so q(K) is
// (R_I / (scale·R))³ with R the Euclidean circumradius and a metric length scale·|d| (an
// edge's midpoint metric is eq. 2.18 of its ends' scales). Runs for every new tet (26 per
// insertion on the cube): R comes from the Inserter's sphere cache, the edges from the raw
// coordinates.
double Refiner::evaluateIsotropic(TetId t, const std::uint32_t* tv, double scale) const {
  // The circumradius from the Inserter's sphere cache (the same arithmetic as
  // refine3d::circumcentreOffset: del3d::circumcentreOffset).
  const double r2 = del3d::sphereRadius2(inserter_.sphere(t));
  double q = 0;
  if (!std::isnan(r2)) {
    const double r = refine3d::kIdealCircumradius / (scale * std::sqrt(r2));
    q = r * r * r;
  }
  if (q < o_.qualityThreshold) return q;
  const double* p[4] = {mesh_.coords(VertexId(tv[0])), mesh_.coords(VertexId(tv[1])), mesh_.coords(VertexId(tv[2])),
                        mesh_.coords(VertexId(tv[3]))};
  // Squared lengths against the prefilter first (local data, no root), then the boundary test.
  const double shortEnough = o_.edgeLengthMax / (scale * kEdgePrefilter);
  for (const auto& e : kEdges) {
    const double* a = p[e[0]];
    const double* b = p[e[1]];
    const double dx = b[0] - a[0], dy = b[1] - a[1], dz = b[2] - a[2];
    const double l2 = (dx * dx + dy * dy) + dz * dz;
    if (l2 <= shortEnough * shortEnough) continue;
    const VertexId va(tv[e[0]]), vb(tv[e[1]]);
    if (s_.isFixed(va) && s_.isFixed(vb)) continue;
    if (refine3d::edgeLengthScale(vt_.scale(va), vt_.scale(vb)) * std::sqrt(l2) > o_.edgeLengthMax)
      return 0.95 * o_.qualityThreshold;
  }
  return q;
}

void Refiner::enqueue(TetId t) {
  heap_.renew(t);
  if (t.index >= postponed_.size()) postponed_.resize(std::size_t{t.index} + 1, 0);  // reserved: reserveFor
  postponed_[t.index] = 0;
  const double q = evaluate(t);
  if (q < o_.qualityThreshold) heap_.push(t, q);
}

bool Refiner::longestInnerEdgeMidpoint(TetId k, const Mat3& m, const TetPoints& tp, Vec3& out) const {
  std::array<std::pair<double, int>, 6> len;
  for (int e = 0; e < 6; ++e) len[e] = {(m * (tp.p[kEdges[e][1]] - tp.p[kEdges[e][0]])).norm(), e};
  std::sort(len.begin(), len.end(), [](const auto& x, const auto& y) {
    return x.first > y.first || (x.first == y.first && x.second < y.second);
  });
  for (const auto& [l, e] : len) {
    if (refine3d::isBoundaryEdge(s_, k, kEdges[e][0], kEdges[e][1])) continue;
    out = 0.5 * (tp.p[kEdges[e][0]] + tp.p[kEdges[e][1]]);
    return true;
  }
  return false;
}

// Is p within minBoundaryDistance (in m) of the plane of a hull or embedded face of tet c?
bool Refiner::nearHull(const Vec3& p, const Metric3d& m, TetId c) const {
  for (int i = 0; i < 4; ++i) {
    if (mesh_.neighbour(c, i).valid() && !mesh_.isConstrained(c, i)) continue;  // hull and embedded faces
    const std::uint32_t* tv = mesh_.tetVertices(c);
    const Vec3 a = m.apply(mesh_.point(VertexId(tv[del3d::kFaceVertex[i][0]])));
    const Vec3 b = m.apply(mesh_.point(VertexId(tv[del3d::kFaceVertex[i][1]])));
    const Vec3 d = m.apply(mesh_.point(VertexId(tv[del3d::kFaceVertex[i][2]])));
    const Vec3 n = (b - a).cross(d - a);
    if (std::abs(n.dot(m.apply(p) - a)) < o_.minBoundaryDistance * n.norm()) return true;
  }
  return false;
}

// Is a vertex of tet c, of its neighbours or of theirs closer to p than
// kCircumsphereMargin · sphere.radius in sphere.metric?
bool Refiner::insideSphere(const Vec3& p, const Sphere& sphere, TetId c) const {
  const double r = kCircumsphereMargin * sphere.radius;
  auto inside = [&](TetId t) {
    for (int i = 0; i < 4; ++i)
      if ((*sphere.metric * (mesh_.point(mesh_.vertex(t, i)) - p)).norm() < r) return true;
    return false;
  };
  if (inside(c)) return true;
  for (int i = 0; i < 4; ++i) {
    const TetId n = mesh_.neighbour(c, i);
    if (!n.valid()) continue;
    if (inside(n)) return true;
    for (int j = 0; j < 4; ++j) {
      const TetId n2 = mesh_.neighbour(n, j);
      if (n2.valid() && n2 != c && inside(n2)) return true;
    }
  }
  return false;
}

Refiner::Outcome Refiner::tryInsert(const Vec3& p, TetId k, bool mle, const Sphere& sphere) {
  const double xyz[3] = {p.x(), p.y(), p.z()};
  const del3d::LocateResult loc = del3d::locate(mesh_, xyz, k, rng_);
  if (loc.status == del3d::LocateStatus::Outside) return Outcome::Outside;
  if (loc.status == del3d::LocateStatus::OnVertex) return Outcome::Close;
  const Metric3d mp = cs_.getMetric(p);
  for (int i = 0; i < 4; ++i)
    if (mp.length(mesh_.point(mesh_.vertex(loc.tet, i)) - p) < o_.minVertexDistance) return Outcome::Close;
  if (mle && nearHull(p, mp, loc.tet)) return Outcome::Close;
  if (sphere.metric && insideSphere(p, sphere, loc.tet)) return Outcome::Close;
  del3d::InsertOptions io;
  io.start = loc.tet;
  io.located = &loc;
  // An isotropic M(P) = I/h gives the same in-sphere signs as the identity, exactly.
  io.transform = isotropicScale(mp.matrix()) > 0 ? nullptr : &mp.matrix();
  io.mustRemove = k;
  const del3d::InsertResult r = inserter_.insert(p, io);
  switch (r.status) {
    case del3d::InsertStatus::Inserted:
      break;
    case del3d::InsertStatus::Outside:
      return Outcome::Outside;
    case del3d::InsertStatus::Duplicate:
      return Outcome::Close;
    case del3d::InsertStatus::Pointless:
      return Outcome::Metric;
    case del3d::InsertStatus::Refused:
      return Outcome::Refused;
  }
  s_.node.resize(mesh_.numVertices(), -1);
  vt_.add(r.vertex, mp.matrix());
  ++st_.inserted;
  for (const TetId t : inserter_.newTets()) enqueue(t);
  return Outcome::Inserted;
}

bool Refiner::refine(TetId k, double q) {
  const TetPoints tp = pointsOf(mesh_, k);
  const Mat3 m = vt_.tetLengthMetric(mesh_.tetVertices(k));
  const bool mleFirst = q < o_.methodSwitch;
  const bool anisotropic = !(isotropicScale(m) > 0);
  for (int attempt = 0; attempt < (mleFirst ? 2 : 1); ++attempt) {
    const bool mle = attempt == 0 && mleFirst;
    Vec3 p;
    const bool placed = mle ? longestInnerEdgeMidpoint(k, m, tp, p)
                            : refine3d::metricCircumcentre(m, tp.p[0], tp.p[1], tp.p[2], tp.p[3], p);
    if (!placed) continue;
    Sphere sphere;
    if (!mle && anisotropic) sphere = {&m, (m * (tp.p[0] - p)).norm()};
    switch (tryInsert(p, k, mle, sphere)) {
      case Outcome::Inserted:
        ++(mle ? st_.insertedMLE : st_.insertedCCS);
        return true;
      case Outcome::Outside:
        ++st_.cancelledOutside;
        return false;  // retried later, no MLE
      case Outcome::Close:
        ++st_.cancelledClose;
        break;
      case Outcome::Metric:
        ++st_.cancelledMetric;
        break;
      case Outcome::Refused:
        ++st_.cancelledRefused;
        break;
    }
  }
  return false;
}

void Refiner::process(const refine3d::RefineQueue::Entry& e) {
  const TetId k(e.tet);
  if (refine(k, e.q)) {
    if (o_.progress && ++sinceProgress_ >= o_.progressInterval) {
      sinceProgress_ = 0;
      // q(K_0) of eq. 6.1: the tet just refined, the front of the refinement (the heap's top
      // may be a tet at the boundary that cannot be refined, with q near 0).
      o_.progress({mesh_.numTets(), e.q, predictTetCount(mesh_.numTets(), e.q, o_.qualityThreshold)});
    }
    return;
  }
  // 5.5.2: K cannot be refined now; retry it later with a raised q.
  if (postponed_[k.index] < o_.maxPostpones) {
    ++postponed_[k.index];
    const double raised = std::min<double>(e.q * o_.postponeFactor + 1e-3, std::nextafter(o_.qualityThreshold, 0.0));
    heap_.push(k, raised);
  } else {
    ++st_.abandoned;
  }
}

VolumeRefineStats Refiner::run() {
  st_.initialTets = mesh_.numTets();
  st_.predictedInitial = refine3d::predictTetCount(mesh_, vt_);
  // Guard against a refinement that would not end (e.g. a metric far finer than asked for):
  // about budgetFactor times the predicted final number of tets, in vertices.
  const double guard =
      o_.budgetFactor * std::max(st_.predictedInitial, kMinBudgetTets) + static_cast<double>(mesh_.numVertices());
  maxVertices_ = static_cast<std::size_t>(std::min(static_cast<double>(o_.maxVertices), guard));
  // Sec. 6.5: the prediction sizes the mesh arrays once (no doubling and copying as they
  // grow: the peak memory of the phase).
  reserveFor(st_.predictedInitial);
  inserter_.cacheSpheres();
  s_.node.resize(mesh_.numVertices(), -1);
  for (std::uint32_t k = 0; k < mesh_.tetSlots(); ++k)
    if (mesh_.isAlive(TetId(k))) enqueue(TetId(k));
  std::vector<refine3d::RefineQueue::Entry> batch;
  std::vector<Vec3> centres;
  refine3d::RefineQueue::Entry e;
  for (;;) {  // bounded: every batch pops the heap, insertions stop at maxVertices_
    checkCancel(o_.cancel, "volume refinement");
    // The worst tets of the heap, refined in the Hilbert order of their centroids.
    const std::size_t want = std::clamp<std::size_t>(heap_.size() / o_.batchDivisor, 1, o_.maxBatch);
    batch.clear();
    centres.clear();
    while (batch.size() < want && heap_.pop(mesh_, e)) batch.push_back(e);
    // Centroids, with the tets' vertices and then their coordinates requested ahead (the
    // batch is spread over the whole mesh: every tet is a cache miss).
    for (std::size_t i = 0; i < batch.size(); ++i) {
      if (i + 2 * kPrefetchAhead < batch.size()) mesh_.prefetchVertices(TetId(batch[i + 2 * kPrefetchAhead].tet));
      if (i + kPrefetchAhead < batch.size()) mesh_.prefetchCoords(TetId(batch[i + kPrefetchAhead].tet));
      centres.push_back(pointsOf(mesh_, TetId(batch[i].tet)).centroid());
    }
    if (batch.empty()) break;
    heap_.compactIfGrown(mesh_);
    heap_.releaseDrained();
    const std::vector<std::uint32_t> order =
        batch.size() > 1 ? del3d::hilbertOrder(centres) : std::vector<std::uint32_t>{0};
    for (const std::uint32_t i : order) {
      if (mesh_.numVertices() >= maxVertices_) {
        st_.budgetExhausted = true;
        break;
      }
      if (heap_.current(mesh_, batch[i])) process(batch[i]);
    }
    if (st_.budgetExhausted) break;
  }
  st_.finalTets = mesh_.numTets();
  return st_;
}

}  // namespace

namespace refine3d {

double predictTetCount(const del3d::TetMesh& mesh, const VertexTensors& vt) {
  double sum = 0;
  for (std::uint32_t k = 0; k < mesh.tetSlots(); ++k) {
    const TetId t(k);
    if (!mesh.isAlive(t)) continue;
    const TetPoints tp = pointsOf(mesh, t);
    const double vol = (tp.p[1] - tp.p[0]).cross(tp.p[2] - tp.p[0]).dot(tp.p[3] - tp.p[0]) / 6.0;
    const std::uint32_t* tv = mesh.tetVertices(t);
    double scale;
    const double det = vt.tetScale(tv, scale) ? scale * scale * scale : vt.tetMetric(tv).determinant();
    sum += std::abs(vol) * det;
  }
  return sum / kIdealVolume;
}

}  // namespace refine3d

double refinementQuality(const Metric3d& m, const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
  return refine3d::metricSphereQuality(m.matrix(), a, b, c, d);
}

double predictTetCount(const SolidTetMesh& s, const ControlSpace3d& cs) {
  const refine3d::VertexTensors vt(s.mesh, cs);
  return predictTetCount(s.mesh, vt);
}

double predictTetCount(std::size_t currentTets, double worstQuality, double qualityThreshold) {
  const double n = static_cast<double>(currentTets);
  if (!(worstQuality > 0) || worstQuality >= qualityThreshold) return n;
  return n * qualityThreshold / worstQuality;
}

VolumeRefineStats refineVolume(SolidTetMesh& s, const ControlSpace3d& cs, const VolumeRefineOptions& o,
                               refine3d::VertexTensorTable* tensors) {
  const std::size_t before = s.mesh.numVertices();
  VolumeRefineStats st;
  {
    Refiner r(s, cs, o);
    st = r.run();
    if (tensors) *tensors = r.releaseTensors();
  }
  if (o.renumber) {
    const std::vector<std::uint32_t> newVertex = renumberSpatially(s, before);
    if (tensors) tensors->renumber(newVertex);
  }
  return st;
}

std::vector<std::uint32_t> renumberSpatially(SolidTetMesh& s, std::size_t firstVertex) {
  del3d::TetMesh& mesh = s.mesh;
  const std::size_t nv = mesh.numVertices();
  if (firstVertex > nv) firstVertex = nv;
  std::vector<Vec3> at;
  at.reserve(nv - firstVertex);
  for (std::size_t v = firstVertex; v < nv; ++v) at.push_back(mesh.point(VertexId(static_cast<std::uint32_t>(v))));
  std::vector<std::uint32_t> newVertex(nv);
  for (std::size_t v = 0; v < firstVertex; ++v) newVertex[v] = static_cast<std::uint32_t>(v);
  {
    const std::vector<std::uint32_t> order = del3d::hilbertOrder(at);
    for (std::size_t k = 0; k < order.size(); ++k)
      newVertex[firstVertex + order[k]] = static_cast<std::uint32_t>(firstVertex + k);
  }
  std::vector<int> node(nv, -1);
  for (std::size_t v = 0; v < nv && v < s.node.size(); ++v) node[newVertex[v]] = s.node[v];
  // Tets by their highest new vertex number (counting sort, stable in the old slot order).
  std::vector<std::uint32_t> first(nv + 1, 0);
  auto key = [&](std::uint32_t t) {
    const std::uint32_t* tv = mesh.tetVertices(TetId(t));
    return std::max({newVertex[tv[0]], newVertex[tv[1]], newVertex[tv[2]], newVertex[tv[3]]});
  };
  for (std::uint32_t t = 0; t < mesh.tetSlots(); ++t)
    if (mesh.isAlive(TetId(t))) ++first[key(t) + 1];
  for (std::size_t v = 0; v < nv; ++v) first[v + 1] += first[v];
  std::vector<std::uint32_t> newTet(mesh.tetSlots(), del3d::kNone);
  for (std::uint32_t t = 0; t < mesh.tetSlots(); ++t)
    if (mesh.isAlive(TetId(t))) newTet[t] = first[key(t)]++;
  mesh.renumber(newVertex, newTet);
  s.node = std::move(node);
  return newVertex;
}

}  // namespace aniso
