#include "mesher/delaunay3d/Inserter.h"

#include <algorithm>
#include <bit>

#include "mesher/delaunay3d/TransformPoint.h"
#include "mesher/predicates/Predicates.h"

namespace aniso::del3d {
namespace {

constexpr std::uint8_t kInCavity = TetMesh::kMarkA;
constexpr std::uint8_t kRejected = TetMesh::kMarkB;
/// collectBoundary requests the vertex data of the cavity tet this many places ahead.
constexpr std::size_t kMarksAhead = 2;

// orient3d of the tet tv with its vertex i replaced by p (> 0: p on the inner side of face i).
inline double faceOrient(const TetMesh& mesh, const std::uint32_t* tv, int i, const double* p) {
  const double* c[4] = {mesh.coords(VertexId(tv[0])), mesh.coords(VertexId(tv[1])),
                        mesh.coords(VertexId(tv[2])), mesh.coords(VertexId(tv[3]))};
  c[i] = p;
  return predicates::orient3d(c[0], c[1], c[2], c[3]);
}

inline std::uint32_t edgeHash(std::uint32_t a, std::uint32_t b) {
  const std::uint32_t h = (a * 0x9E3779B1u + b) * 0x85EBCA77u;
  return h ^ (h >> 16);
}

// The two local indices of a tet other than i and j (i != j).
inline void otherTwo(int i, int j, int& x, int& y) {
  static constexpr int kOther[4][4][2] = {
      {{-1, -1}, {2, 3}, {1, 3}, {1, 2}},
      {{2, 3}, {-1, -1}, {0, 3}, {0, 2}},
      {{1, 3}, {0, 3}, {-1, -1}, {0, 1}},
      {{1, 2}, {0, 2}, {0, 1}, {-1, -1}}};
  x = kOther[i][j][0];
  y = kOther[i][j][1];
}

// For the new tet of a cavity face with the point at local index i: its three other
// faces j and, for each, the local indices x, y of the cavity-face edge it contains.
constexpr int kSideFaces[4][3][3] = {
    {{1, 2, 3}, {2, 1, 3}, {3, 1, 2}},
    {{0, 2, 3}, {2, 0, 3}, {3, 0, 2}},
    {{0, 1, 3}, {1, 0, 3}, {3, 0, 1}},
    {{0, 1, 2}, {1, 0, 2}, {2, 0, 1}}};

}  // namespace

Inserter::Inserter(TetMesh& mesh, std::uint32_t seed) : mesh_(mesh), rng_(seed ? seed : 1u) {}

void Inserter::nextStamp() {
  if (++stamp_ == 0) {
    for (VertexMark& v : vmark_) v.stamp = 0;
    std::fill(mstamp_.begin(), mstamp_.end(), 0u);
    for (EdgeSlot& e : edges_) e.stamp = 0;
    for (PairSlot& e : pairs_) e.stamp = 0;
    stamp_ = 1;
  }
}

const double* Inserter::transformed(std::uint32_t v) const {
  double* q = &mxyz_[3 * std::size_t{v}];
  if (mstamp_[v] != stamp_) {
    mstamp_[v] = stamp_;
    transformPoint(*m_, mesh_.coords(VertexId(v)), q);
  }
  return q;
}

void Inserter::cacheSpheres() {
  spheresOn_ = true;
  spheres_.reserve(mesh_.tetCapacity());
  spheres_.resize(mesh_.tetSlots());
  for (std::uint32_t k = 0; k < mesh_.tetSlots(); ++k) {
    if (!mesh_.isAlive(TetId(k))) continue;
    const std::uint32_t* tv = mesh_.tetVertices(TetId(k));
    cachedSphere(mesh_.coords(VertexId(tv[0])), mesh_.coords(VertexId(tv[1])), mesh_.coords(VertexId(tv[2])),
                 mesh_.coords(VertexId(tv[3])), spheres_[k]);
  }
}

bool Inserter::inConflict(TetId t) const {
  ++inSphereTests_;
  if (!m_ && spheresOn_) {
    const int side = sphereSide(spheres_[t.index], p_);
    if (side != 0) return side > 0;
  }
  const std::uint32_t* tv = mesh_.tetVertices(t);
  if (!m_) {
    return predicates::insphere(mesh_.coords(VertexId(tv[0])), mesh_.coords(VertexId(tv[1])),
                                mesh_.coords(VertexId(tv[2])), mesh_.coords(VertexId(tv[3])), p_) > 0;
  }
  const double* a = transformed(tv[0]);
  const double* b = transformed(tv[1]);
  const double* c = transformed(tv[2]);
  const double* d = transformed(tv[3]);
  // A tet flattened (or turned over) by rounding of M·x: its in-sphere sign is taken
  // relative to its transformed orientation; a flat one is not in conflict.
  const double s = predicates::orient3d(a, b, c, d);
  if (s == 0) return false;
  const double r = predicates::insphere(a, b, c, d, mp_);
  return s > 0 ? r > 0 : r < 0;
}

// K_c, and every other tet containing p when p lies on a face or an edge of K_c (they are
// all in conflict mathematically; forcing them protects against rounding of M·p).
void Inserter::seedCavity(const LocateResult& loc) {
  cavity_.clear();
  rejected_.clear();
  const TetId t = loc.tet;
  mesh_.setMark(t, kInCavity);
  cavity_.push_back(t);
  if (loc.status == LocateStatus::OnFace) {
    const int f = std::countr_zero(loc.zeroFaces);
    const TetId n = mesh_.neighbour(t, f);
    if (n.valid() && !mesh_.isConstrained(t, f)) {
      mesh_.setMark(n, kInCavity);
      cavity_.push_back(n);
    }
  } else if (loc.status == LocateStatus::OnEdge) {
    // Rotate around the edge in both directions; state (tet, x, y): cross the face opposite x.
    const int j = std::countr_zero(loc.zeroFaces);
    const int k = std::countr_zero(loc.zeroFaces & ~(1u << j));
    int ea, eb;
    otherTwo(j, k, ea, eb);
    const VertexId a = mesh_.vertex(t, ea), b = mesh_.vertex(t, eb);
    for (int dir = 0; dir < 2; ++dir) {
      TetId cur = t;
      VertexId x = mesh_.vertex(t, dir == 0 ? j : k), y = mesh_.vertex(t, dir == 0 ? k : j);
      for (std::size_t guard = 0; guard < 1024; ++guard) {
        const int ix = mesh_.localIndex(cur, x);
        const TetId n = mesh_.neighbour(cur, ix);
        if (!n.valid() || mesh_.isConstrained(cur, ix) || n == t) break;
        VertexId z;
        for (int m = 0; m < 4; ++m) {
          const VertexId w = mesh_.vertex(n, m);
          if (w != a && w != b && w != y) z = w;
        }
        if (!mesh_.hasMark(n, kInCavity)) {
          mesh_.setMark(n, kInCavity);
          cavity_.push_back(n);
        }
        cur = n;
        x = y;
        y = z;
      }
    }
  }
}

// Depth-first (breadth-first order, same set) search of the conflict region through
// non-constrained faces; tested tets outside it are marked so each is tested once.
void Inserter::growCavity() {
  const bool spheres = !m_ && spheresOn_;
  for (std::size_t k = 0; k < cavity_.size(); ++k) {
    const TetId t = cavity_[k];
    // The four neighbours' flags and spheres are requested together, not one miss after
    // another.
    for (int i = 0; i < 4; ++i) {
      const std::uint32_t code = mesh_.adjacentCode(t, i);
      if (code == kNone) continue;
      mesh_.prefetchAdjacency(codeTet(code));
      if (spheres) __builtin_prefetch(&spheres_[code >> 2]);
    }
    for (int i = 0; i < 4; ++i) {
      const std::uint32_t code = mesh_.adjacentCode(t, i);
      if (code == kNone || mesh_.isConstrained(t, i)) continue;
      const TetId n = codeTet(code);
      if (mesh_.flags(n) & (kInCavity | kRejected)) continue;
      if (inConflict(n)) {
        mesh_.setMark(n, kInCavity);
        mesh_.prefetchVertices(n);  // for collectBoundary (the sphere test did not need them)
        cavity_.push_back(n);
      } else {
        mesh_.setMark(n, kRejected);
        rejected_.push_back(n);
      }
    }
  }
}

// Face i of cavity tet t (vertices tv) is shared with the tested, rejected tet n (code):
// p is strictly inside t's circumsphere S_t and not strictly inside S_n. Both spheres pass
// through the face's circle, so their power difference pow_t − pow_n is affine and vanishes
// on the face's plane, negative at p; when t's apex is certified strictly outside S_n (the
// pair is locally Delaunay) it is negative there too: p lies strictly on t's side, which is
// the orient3d test this replaces. Only with the cached spheres, the identity, and the
// cavity as grown (not after pruning, which rejects tets that contain p).
bool Inserter::visibleByPower(const std::uint32_t* tv, int i, std::uint32_t code, bool skip) const {
  if (!powerTest_ || skip) return false;
  return sphereSide(spheres_[code >> 2], mesh_.coords(VertexId(tv[i]))) < 0;
}

// Builds the cavity faces and the new tets' vertices; true when every new tet is positive,
// no constrained face is interior to the cavity and no vertex would be stranded.
bool Inserter::collectBoundary() {
  nextStamp();
  cavityVertices_ = 0;
  const std::size_t cap = 4 * cavity_.size() + 1;  // + 1: matchEdges' dummy
  if (boundary_.size() < cap) boundary_.resize(std::max(cap, 2 * boundary_.size()));
  std::size_t nb = 0;
  bool ok = true;
  // Written without data-dependent branches where the outcome is a coin flip (new
  // vertex or not, neighbour in the cavity or not): every face is written to the next
  // slot, and the slot is kept only for a cavity face.
  for (std::size_t c = 0; c < cavity_.size(); ++c) {
    const TetId t = cavity_[c];
    if (c + kMarksAhead < cavity_.size()) {  // the vertex marks and coordinates of a later tet
      const std::uint32_t* later = mesh_.tetVertices(cavity_[c + kMarksAhead]);
      for (int i = 0; i < 4; ++i) __builtin_prefetch(&vmark_[later[i]]);
      mesh_.prefetchCoords(cavity_[c + kMarksAhead]);
    }
    const std::uint32_t* tv = mesh_.tetVertices(t);
    std::uint32_t loc[4];
    for (int i = 0; i < 4; ++i) {
      const std::uint32_t v = tv[i];
      VertexMark& mark = vmark_[v];
      const bool isNew = mark.stamp != stamp_;
      loc[i] = isNew ? cavityVertices_ : mark.local;
      mark.stamp = stamp_;
      mark.local = loc[i];
      cavityVertices_ += isNew ? 1u : 0u;
    }
    const std::uint8_t flags = mesh_.flags(t);
    for (int i = 0; i < 4; ++i) {
      const std::uint32_t code = mesh_.adjacentCode(t, i);
      const bool hull = code == kNone;
      const bool inside = !hull && (mesh_.flags(TetId(hull ? 0u : code >> 2)) & kInCavity);
      const bool constrained = (flags >> i) & 1u;
      BoundaryFace& f = boundary_[nb];
      for (int m = 0; m < 4; ++m) {
        f.v[m] = tv[m];
        f.l[m] = loc[m];
      }
      f.v[i] = kNone;  // the new vertex, known at commit
      f.outer = code;
      f.face = static_cast<std::uint8_t>(i);
      f.constrained = constrained;
      nb += inside ? 0 : 1;
      ok = ok && !(inside && constrained);
      // Faces shared with a tested, rejected tet are visible from p in a Delaunay mesh
      // (identity metric): p outside that tet's circumsphere puts it on our side.
      if (!inside && (!certified_ || hull || constrained) && !visibleByPower(tv, i, code, hull || constrained) &&
          faceOrient(mesh_, tv, i, p_) <= 0)
        ok = false;
    }
  }
  nb_ = nb;
  // A ball bounded by F triangles has F/2 + 2 boundary vertices; more means one is inside.
  return ok && cavityVertices_ == nb / 2 + 2;
}

// Slow path (rounding of M·p, constrained faces, non-Delaunay meshes): drops offending
// tets until collectBoundary() succeeds. False when K_c itself has to go.
bool Inserter::pruneCavity() {
  for (;;) {
    ring_.clear();  // tets to drop
    for (const TetId t : cavity_) {
      const std::uint32_t* tv = mesh_.tetVertices(t);
      for (int i = 0; i < 4; ++i) {
        const std::uint32_t code = mesh_.adjacentCode(t, i);
        if (code != kNone && mesh_.hasMark(codeTet(code), kInCavity)) {
          if (mesh_.isConstrained(t, i)) ring_.push_back(codeTet(code) == located_ ? t : codeTet(code));
        } else if (faceOrient(mesh_, tv, i, p_) <= 0) {
          ring_.push_back(t);
        }
      }
    }
    if (ring_.empty()) {
      // Stranded vertices: in a cavity tet but on no cavity face.
      nextStamp();
      for (const TetId t : cavity_) {
        for (int i = 0; i < 4; ++i) {
          const std::uint32_t code = mesh_.adjacentCode(t, i);
          if (code != kNone && mesh_.hasMark(codeTet(code), kInCavity)) continue;
          for (int m = 0; m < 3; ++m) vmark_[mesh_.tetVertices(t)[kFaceVertex[i][m]]].stamp = stamp_;
        }
      }
      for (const TetId t : cavity_) {
        const std::uint32_t* tv = mesh_.tetVertices(t);
        if (t == located_) continue;
        for (int m = 0; m < 4; ++m) {
          if (vmark_[tv[m]].stamp != stamp_) {
            vmark_[tv[m]].stamp = stamp_;  // one tet per stranded vertex is enough
            ring_.push_back(t);
            break;
          }
        }
      }
      if (ring_.empty()) return collectBoundary();
    }
    for (const TetId t : ring_) {
      if (t == located_) return false;
      if (mesh_.hasMark(t, kInCavity)) {
        mesh_.clearMark(t, kInCavity);
        mesh_.setMark(t, kRejected);
        rejected_.push_back(t);
      }
    }
    std::erase_if(cavity_, [this](TetId t) { return !mesh_.hasMark(t, kInCavity); });
  }
}

// Records or completes the pairing of new face (k, j) through an edge slot holding the
// first face seen on that edge (kNone once paired). False on a third face.
bool Inserter::link(std::uint32_t& slotRef, std::size_t k, int j) {
  if (slotRef == kNone) return false;
  const std::uint32_t ref = static_cast<std::uint32_t>(4 * k + j);
  boundary_[k].link[j] = slotRef;
  boundary_[slotRef >> 2].link[slotRef & 3u] = ref;
  slotRef = kNone;
  return true;
}

// Pairs the faces of the new tets through the edges of the cavity faces. False when the
// cavity surface is not a closed 2-manifold (never for a star-shaped cavity).
// Requires the local numbers (vmark_) from the last collectBoundary().
bool Inserter::matchEdges() {
  constexpr std::uint32_t kDirectMax = 96;
  const std::uint32_t nv = cavityVertices_;
  if (nv > kDirectMax) return matchEdgesHashed();
  if (pairs_.empty()) pairs_.resize(std::size_t{kDirectMax} * (kDirectMax - 1) / 2);
  nextStamp();
  // Branch-free pairing (the first/second outcome is a coin flip for the predictor): the
  // first face on an edge writes its link into a dummy face past the end, and gets its
  // own link when the second one arrives.
  const std::size_t nf = nb_;
  const std::uint32_t dummy = static_cast<std::uint32_t>(4 * nf);
  std::size_t matched = 0;
  std::uint32_t bad = 0;
  for (std::size_t k = 0; k < nf; ++k) {
    BoundaryFace& f = boundary_[k];
    for (int e = 0; e < 3; ++e) {
      const int j = kSideFaces[f.face][e][0], x = kSideFaces[f.face][e][1], y = kSideFaces[f.face][e][2];
      const std::uint32_t a = std::min(f.l[x], f.l[y]), b = std::max(f.l[x], f.l[y]);
      PairSlot& s = pairs_[std::size_t{b} * (b - 1) / 2 + a];
      const std::uint32_t ref = static_cast<std::uint32_t>(4 * k + j);
      // Masks, not branches: all ones when this is the first face on the edge / a third.
      const std::uint32_t sref = s.ref;
      const std::uint32_t first = 0u - static_cast<std::uint32_t>(s.stamp != stamp_);
      const std::uint32_t third = ~first & (0u - static_cast<std::uint32_t>(sref == kNone));
      const std::uint32_t toDummy = first | third;
      const std::uint32_t other = (dummy & toDummy) | (sref & ~toDummy);
      s.stamp = stamp_;
      s.ref = (ref & first) | (kNone & ~first);
      f.link[j] = other;
      boundary_[other >> 2].link[other & 3u] = ref;
      matched += ~first & 1u;
      bad |= third;
    }
  }
  return bad == 0 && 2 * matched == 3 * nf;
}

bool Inserter::matchEdgesHashed() {
  const std::size_t halfEdges = 3 * nb_;
  std::size_t size = 64;
  while (size < 2 * halfEdges) size *= 2;
  if (edges_.size() < size) edges_.resize(size);
  const std::uint32_t mask = static_cast<std::uint32_t>(size - 1);
  nextStamp();
  std::size_t matched = 0;
  for (std::size_t k = 0; k < nb_; ++k) {
    const BoundaryFace& f = boundary_[k];
    for (int e = 0; e < 3; ++e) {
      const int j = kSideFaces[f.face][e][0], x = kSideFaces[f.face][e][1], y = kSideFaces[f.face][e][2];
      const std::uint32_t a = std::min(f.v[x], f.v[y]), b = std::max(f.v[x], f.v[y]);
      std::uint32_t h = edgeHash(a, b) & mask;
      for (;;) {
        EdgeSlot& s = edges_[h];
        if (s.stamp != stamp_) {
          s = EdgeSlot{stamp_, a, b, static_cast<std::uint32_t>(4 * k + j)};
          break;
        }
        if (s.a == a && s.b == b) {
          if (!link(s.ref, k, j)) return false;
          ++matched;
          break;
        }
        h = (h + 1) & mask;
      }
    }
  }
  return 2 * matched == halfEdges;
}

void Inserter::clearMarks() {
  for (const TetId t : cavity_) mesh_.clearMark(t, kInCavity);
  for (const TetId t : rejected_) mesh_.clearMark(t, kRejected);
}

void Inserter::commit() {
  for (const TetId t : rejected_) mesh_.clearMark(t, kRejected);
  const VertexId nv = mesh_.addVertex(Vec3(p_[0], p_[1], p_[2]));
  removed_.assign(cavity_.begin(), cavity_.end());
  for (const TetId t : cavity_) mesh_.freeTet(t);
  newTets_.clear();
  for (std::size_t k = 0; k < nb_; ++k) {
    BoundaryFace& f = boundary_[k];
    f.v[f.face] = nv.index;
    newTets_.push_back(mesh_.createTet(VertexId(f.v[0]), VertexId(f.v[1]), VertexId(f.v[2]), VertexId(f.v[3])));
  }
  if (spheresOn_) {
    if (spheres_.size() < mesh_.tetSlots()) spheres_.resize(mesh_.tetSlots());
    for (std::size_t k = 0; k < nb_; ++k) {
      const std::uint32_t* v = boundary_[k].v;
      cachedSphere(mesh_.coords(VertexId(v[0])), mesh_.coords(VertexId(v[1])), mesh_.coords(VertexId(v[2])),
                   mesh_.coords(VertexId(v[3])), spheres_[newTets_[k].index]);
    }
  }
  for (std::size_t k = 0; k < nb_; ++k) {
    const BoundaryFace& f = boundary_[k];
    const TetId t = newTets_[k];
    const int i = f.face;
    mesh_.setAdjacentCode(t, i, f.outer);
    if (f.outer != kNone) mesh_.setAdjacentCode(codeTet(f.outer), codeFace(f.outer), faceCode(t, i));
    if (f.constrained) mesh_.setConstrainedBit(t, i, true);
    for (int j = 0; j < 4; ++j) {
      if (j != i) mesh_.setAdjacentCode(t, j, faceCode(newTets_[f.link[j] >> 2], static_cast<int>(f.link[j] & 3u)));
      mesh_.setVertexTet(VertexId(f.v[j]), t);
    }
  }
  last_ = newTets_.back();
}

InsertResult Inserter::insert(const Vec3& p, const InsertOptions& options) {
  InsertResult res;
  TetId start = options.start;
  const Mat3* transform = options.transform;
  p_[0] = p.x();
  p_[1] = p.y();
  p_[2] = p.z();
  m_ = (transform && !transform->isIdentity(0.0)) ? transform : nullptr;
  if (!options.located) {
    if (!start.valid() || !mesh_.isAlive(start)) start = mesh_.isAlive(last_) ? last_ : TetId();
    for (std::uint32_t k = 0; !start.valid() && k < mesh_.tetSlots(); ++k)
      if (mesh_.isAlive(TetId(k))) start = TetId(k);
    if (!start.valid()) {
      res.status = InsertStatus::Outside;
      return res;
    }
  }
  const LocateResult loc = options.located ? *options.located : locate(mesh_, p_, start, rng_);
  res.walkSteps = loc.steps;
  res.tet = loc.tet;
  if (loc.status == LocateStatus::Outside) {
    res.status = InsertStatus::Outside;
    return res;
  }
  if (loc.status == LocateStatus::OnVertex) {
    res.status = InsertStatus::Duplicate;
    res.vertex = loc.vertex;
    return res;
  }
  const std::size_t nv = mesh_.numVertices() + 1;
  if (vmark_.size() < nv) {
    vmark_.resize(std::max(nv, 2 * vmark_.size()));
  }
  nextStamp();
  if (m_) {
    if (mstamp_.size() < nv) {
      mstamp_.resize(std::max(nv, 2 * mstamp_.size()), 0u);
      mxyz_.resize(3 * mstamp_.size());
    }
    transformPoint(*m_, p_, mp_);
  }
  located_ = loc.tet;
  certified_ = m_ == nullptr && mesh_.certifiedDelaunay();
  powerTest_ = m_ == nullptr && spheresOn_;
  seedCavity(loc);
  growCavity();
  bool ok = collectBoundary();
  if (!ok) {
    certified_ = false;  // pruned cavity: the result need not be Delaunay
    powerTest_ = false;
    ok = pruneCavity();
  }
  if (ok && options.mustRemove.valid() &&
      !(mesh_.isAlive(options.mustRemove) && mesh_.hasMark(options.mustRemove, kInCavity))) {
    clearMarks();
    res.status = InsertStatus::Pointless;
    return res;
  }
  ok = ok && matchEdges();
  if (!ok) {
    clearMarks();
    ++refusals_;
    res.status = InsertStatus::Refused;
    return res;
  }
  res.cavityTets = static_cast<std::uint32_t>(cavity_.size());
  commit();
  if (!certified_) mesh_.setCertifiedDelaunay(false);
  res.status = InsertStatus::Inserted;
  res.vertex = VertexId(static_cast<std::uint32_t>(mesh_.numVertices() - 1));
  res.tet = last_;
  return res;
}

}  // namespace aniso::del3d
