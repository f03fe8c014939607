#include "mesher/delaunay/Triangulation2d.h"

#include <algorithm>
#include <cmath>

#include "mesher/core/Error.h"
#include "mesher/delaunay/PlaneTransform.h"
#include "mesher/delaunay/Workspace2d.h"

namespace aniso::del2d {
namespace {

Box2 enlargedBox(const Box2& bounds, double margin) {
  if (bounds.empty() || !bounds.lo.allFinite() || !bounds.hi.allFinite())
    throw MeshingError("Triangulation2d: the bounds are empty or not finite");
  if (!(margin > 0) || !std::isfinite(margin))
    throw MeshingError("Triangulation2d: the box margin must be finite and > 0");
  const double side = bounds.size().maxCoeff();
  const double scale = std::max(bounds.lo.cwiseAbs().maxCoeff(), bounds.hi.cwiseAbs().maxCoeff());
  const double grow = margin * std::max(side, 1e-3 * (1.0 + scale));
  Box2 box;
  box.lo = bounds.lo.array() - grow;
  box.hi = bounds.hi.array() + grow;
  return box;
}

}  // namespace

Triangulation2d::Triangulation2d(const Box2& bounds, const Triangulation2dOptions& options)
    : box_(enlargedBox(bounds, options.boxMargin)),
      seeds_(box_, options.quadtree),
      work_(std::make_unique<Workspace2d>()) {
  for (int k = 0; k < 4; ++k) {
    const Vec2 p((k & 1) ? box_.hi.x() : box_.lo.x(), (k & 2) ? box_.hi.y() : box_.lo.y());
    corners_[k] = addVertex(p);
  }
  const PlaneTransform m(options.transform);
  if (m.orientation() == 0) throw MeshingError("Triangulation2d: the transformation is singular");
  const bool otherDiagonal =
      m.inCircle(xy_[0], xy_[1], xy_[3], m.apply(xy_[2])) > 0;  // corner 2 inside (0, 1, 3)
  if (!otherDiagonal) {
    // Diagonal 0–3: (0, 1, 3) and (0, 3, 2); edge (3, 0) of the first is (0, 3) of the second.
    const TriId t0 = createTriangle(corners_[0], corners_[1], corners_[3]);
    const TriId t1 = createTriangle(corners_[0], corners_[3], corners_[2]);
    link(t0, 1, t1, 2);
    for (int k = 0; k < 4; ++k) setVertexTriangle(corners_[k], k == 2 ? t1 : t0);
  } else {
    // Diagonal 1–2: (0, 1, 2) and (1, 3, 2); edge (1, 2) of the first is edge (2, 1) of the
    // second (opposite its vertex 3, local index 1).
    const TriId t0 = createTriangle(corners_[0], corners_[1], corners_[2]);
    const TriId t1 = createTriangle(corners_[1], corners_[3], corners_[2]);
    link(t0, 0, t1, 1);
    for (int k = 0; k < 4; ++k) setVertexTriangle(corners_[k], k == 3 ? t1 : t0);
  }
}

Triangulation2d::~Triangulation2d() {
  for (detail::AttributeSlot* a : triAttrs_) a->rebind(nullptr);
  for (detail::AttributeSlot* a : vertAttrs_) a->rebind(nullptr);
}

Triangulation2d::Triangulation2d(const Triangulation2d& o)
    : xy_(o.xy_), vtri_(o.vtri_), tv_(o.tv_), tn_(o.tn_), tf_(o.tf_), freeHead_(o.freeHead_),
      live_(o.live_), revision_(o.revision_ + 1), last_(o.last_), box_(o.box_), corners_(o.corners_),
      seeds_(o.seeds_), seeded_(o.seeded_), work_(std::make_unique<Workspace2d>()) {}

Triangulation2d& Triangulation2d::operator=(const Triangulation2d& o) {
  if (this == &o) return *this;
  xy_ = o.xy_, vtri_ = o.vtri_, tv_ = o.tv_, tn_ = o.tn_, tf_ = o.tf_;
  freeHead_ = o.freeHead_, live_ = o.live_, last_ = o.last_, box_ = o.box_;
  revision_ = o.revision_ + 1;
  corners_ = o.corners_, seeds_ = o.seeds_, seeded_ = o.seeded_;
  for (detail::AttributeSlot* a : triAttrs_) a->grow(tf_.size());
  for (detail::AttributeSlot* a : vertAttrs_) a->grow(vtri_.size());
  return *this;
}

Triangulation2d::Triangulation2d(Triangulation2d&& o) noexcept
    : xy_(std::move(o.xy_)), vtri_(std::move(o.vtri_)), tv_(std::move(o.tv_)),
      tn_(std::move(o.tn_)), tf_(std::move(o.tf_)), freeHead_(o.freeHead_), live_(o.live_),
      revision_(o.revision_), last_(o.last_), box_(o.box_), corners_(o.corners_), seeds_(std::move(o.seeds_)),
      seeded_(o.seeded_), work_(std::move(o.work_)), triAttrs_(std::move(o.triAttrs_)),
      vertAttrs_(std::move(o.vertAttrs_)) {
  o.triAttrs_.clear();
  o.vertAttrs_.clear();
  o.work_ = std::make_unique<Workspace2d>();
  rebindAttributes();
}

Triangulation2d& Triangulation2d::operator=(Triangulation2d&& o) noexcept {
  if (this == &o) return *this;
  for (detail::AttributeSlot* a : triAttrs_) a->rebind(nullptr);
  for (detail::AttributeSlot* a : vertAttrs_) a->rebind(nullptr);
  xy_ = std::move(o.xy_), vtri_ = std::move(o.vtri_), tv_ = std::move(o.tv_);
  tn_ = std::move(o.tn_), tf_ = std::move(o.tf_);
  freeHead_ = o.freeHead_, live_ = o.live_, last_ = o.last_, box_ = o.box_;
  revision_ = o.revision_ + 1;
  corners_ = o.corners_, seeds_ = std::move(o.seeds_), seeded_ = o.seeded_;
  std::swap(work_, o.work_);
  triAttrs_ = std::move(o.triAttrs_), vertAttrs_ = std::move(o.vertAttrs_);
  o.triAttrs_.clear();
  o.vertAttrs_.clear();
  rebindAttributes();
  return *this;
}

void Triangulation2d::rebindAttributes() {
  for (detail::AttributeSlot* a : triAttrs_) a->rebind(this);
  for (detail::AttributeSlot* a : vertAttrs_) a->rebind(this);
}

const SeedQuadtree& Triangulation2d::seeds() const {
  for (; seeded_ < xy_.size(); ++seeded_) seeds_.insert(VertexId(seeded_), xy_[seeded_]);
  return seeds_;
}

int Triangulation2d::localIndex(TriId t, VertexId v) const {
  const std::uint32_t* tv = triVertices(t);
  return tv[0] == v.index ? 0 : tv[1] == v.index ? 1 : tv[2] == v.index ? 2 : -1;
}

int Triangulation2d::neighbourIndex(TriId t, TriId u) const {
  const std::uint32_t* tn = triNeighbours(t);
  return tn[0] == u.index ? 0 : tn[1] == u.index ? 1 : tn[2] == u.index ? 2 : -1;
}

void Triangulation2d::setConstrained(TriId t, int i, bool on) {
  setConstrainedBit(t, i, on);
  const TriId u = neighbour(t, i);
  if (!u.valid()) return;
  const int j = neighbourIndex(u, t);
  if (j >= 0) setConstrainedBit(u, j, on);
}

bool Triangulation2d::findEdge(VertexId a, VertexId b, TriId& t, int& i) const {
  if (a.index >= numVertices() || b.index >= numVertices()) return false;
  const TriId start = vertexTriangle(a);
  if (!start.valid() || !isAlive(start)) return false;
  // Counter-clockwise around a, then (if the star is open) clockwise from the start.
  for (int dir = 0; dir < 2; ++dir) {
    TriId cur = start;
    for (std::size_t guard = 0; guard < tf_.size() + 1; ++guard) {
      const int ia = localIndex(cur, a);
      if (ia < 0) return false;  // corrupt star: vertexTriangle does not contain a
      if (vertex(cur, kNext[ia]) == b) {
        t = cur;
        i = kPrev[ia];
        return true;
      }
      cur = neighbour(cur, dir == 0 ? kNext[ia] : kPrev[ia]);
      if (!cur.valid()) break;
      if (cur == start) return false;  // closed star, edge absent
    }
  }
  return false;
}

bool Triangulation2d::setConstrainedEdge(VertexId a, VertexId b, bool on) {
  TriId t;
  int i = 0;
  if (!findEdge(a, b, t, i) && !findEdge(b, a, t, i)) return false;
  setConstrained(t, i, on);
  return true;
}

VertexId Triangulation2d::addVertex(const Vec2& p) {
  const VertexId v(static_cast<std::uint32_t>(xy_.size()));
  xy_.push_back(p);
  vtri_.push_back(kNone);
  ++revision_;
  for (detail::AttributeSlot* a : vertAttrs_) a->grow(vtri_.size());
  return v;
}

TriId Triangulation2d::createTriangle(VertexId a, VertexId b, VertexId c) {
  ANISO_ASSERT(a.index < numVertices() && b.index < numVertices() && c.index < numVertices());
  ANISO_ASSERT(a != b && b != c && c != a);
  TriId t;
  if (freeHead_ != kNone) {
    t = TriId(freeHead_);
    freeHead_ = tn_[3 * std::size_t{t.index}];
  } else {
    if (tf_.size() >= kMaxTriangles) throw MeshingError("Triangulation2d: too many triangles");
    t = TriId(static_cast<std::uint32_t>(tf_.size()));
    tv_.resize(tv_.size() + 3);
    tn_.resize(tn_.size() + 3);
    tf_.push_back(0);
    for (detail::AttributeSlot* at : triAttrs_) at->grow(tf_.size());
  }
  const std::size_t k = 3 * std::size_t{t.index};
  tv_[k] = a.index, tv_[k + 1] = b.index, tv_[k + 2] = c.index;
  tn_[k] = tn_[k + 1] = tn_[k + 2] = kNone;
  tf_[t.index] = 0;
  ++live_;
  ++revision_;
  last_ = t;
  return t;
}

void Triangulation2d::setTriangle(TriId t, VertexId a, VertexId b, VertexId c) {
  ANISO_ASSERT(isAlive(t));
  ANISO_ASSERT(a.index < numVertices() && b.index < numVertices() && c.index < numVertices());
  const std::size_t k = 3 * std::size_t{t.index};
  tv_[k] = a.index, tv_[k + 1] = b.index, tv_[k + 2] = c.index;
  ++revision_;
}

void Triangulation2d::freeTriangle(TriId t) {
  ANISO_ASSERT(isAlive(t));  // not freed twice
  const std::size_t k = 3 * std::size_t{t.index};
  tv_[k] = kFreeMark;
  tv_[k + 1] = tv_[k + 2] = kNone;
  tn_[k] = freeHead_;
  tn_[k + 1] = tn_[k + 2] = kNone;
  tf_[t.index] = 0;
  freeHead_ = t.index;
  --live_;
  ++revision_;
}

void Triangulation2d::reserve(std::size_t vertices, std::size_t triangles) {
  xy_.reserve(vertices);
  vtri_.reserve(vertices);
  tv_.reserve(3 * triangles);
  tn_.reserve(3 * triangles);
  tf_.reserve(triangles);
}

std::size_t Triangulation2d::memoryBytes() const {
  return xy_.capacity() * sizeof(Vec2) + vtri_.capacity() * 4 + tv_.capacity() * 4 +
         tn_.capacity() * 4 + tf_.capacity();
}

void Triangulation2d::attachTriangleAttribute(detail::AttributeSlot* a) {
  triAttrs_.push_back(a);
  a->grow(tf_.size());
}

void Triangulation2d::attachVertexAttribute(detail::AttributeSlot* a) {
  vertAttrs_.push_back(a);
  a->grow(vtri_.size());
}

void Triangulation2d::detachAttribute(detail::AttributeSlot* a) {
  std::erase(triAttrs_, a);
  std::erase(vertAttrs_, a);
}

}  // namespace aniso::del2d
