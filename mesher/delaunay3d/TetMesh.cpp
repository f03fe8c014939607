#include "mesher/delaunay3d/TetMesh.h"

#include "mesher/core/Error.h"

#include <algorithm>

namespace aniso::del3d {

VertexId TetMesh::addVertex(const Vec3& p) {
  if (vtet_.size() >= kFreeMark) throw MeshingError("TetMesh: too many vertices");
  xyz_.push_back(p.x());
  xyz_.push_back(p.y());
  xyz_.push_back(p.z());
  vtet_.push_back(kNone);
  return VertexId(static_cast<std::uint32_t>(vtet_.size() - 1));
}

int TetMesh::localIndex(TetId t, VertexId v) const {
  const std::uint32_t* tv = tetVertices(t);
  for (int i = 0; i < 4; ++i)
    if (tv[i] == v.index) return i;
  return -1;
}

void TetMesh::setConstrained(TetId t, int i, bool on) {
  if (on) certified_ = false;
  setConstrainedBit(t, i, on);
  const std::uint32_t code = adjacentCode(t, i);
  if (code != kNone) setConstrainedBit(codeTet(code), codeFace(code), on);
}

TetId TetMesh::createTet(VertexId a, VertexId b, VertexId c, VertexId d) {
  ANISO_ASSERT(a.index < numVertices() && b.index < numVertices() && c.index < numVertices() &&
               d.index < numVertices());
  ANISO_ASSERT(a != b && a != c && a != d && b != c && b != d && c != d);
  std::uint32_t t;
  if (freeHead_ != kNone) {
    t = freeHead_;
    freeHead_ = tn_[4 * std::size_t{t}];
    tf_[t] = 0;
  } else {
    if (tf_.size() >= kMaxTets) throw MeshingError("TetMesh: too many tetrahedra");
    t = static_cast<std::uint32_t>(tf_.size());
    tv_.resize(tv_.size() + 4);
    tn_.resize(tn_.size() + 4);
    tf_.push_back(0);
  }
  const std::size_t k = 4 * std::size_t{t};
  tv_[k] = a.index;
  tv_[k + 1] = b.index;
  tv_[k + 2] = c.index;
  tv_[k + 3] = d.index;
  tn_[k] = tn_[k + 1] = tn_[k + 2] = tn_[k + 3] = kNone;
  ++live_;
  return TetId(t);
}

void TetMesh::freeTet(TetId t) {
  ANISO_ASSERT(isAlive(t));  // not freed twice
  const std::size_t k = 4 * std::size_t{t.index};
  tv_[k] = kFreeMark;
  tv_[k + 1] = tv_[k + 2] = tv_[k + 3] = kNone;
  tn_[k] = freeHead_;
  tn_[k + 1] = tn_[k + 2] = tn_[k + 3] = kNone;
  tf_[t.index] = 0;
  freeHead_ = t.index;
  --live_;
}

void TetMesh::reserve(std::size_t vertices, std::size_t tets) {
  xyz_.reserve(3 * vertices);
  vtet_.reserve(vertices);
  tv_.reserve(4 * tets);
  tn_.reserve(4 * tets);
  tf_.reserve(tets);
}

void TetMesh::renumber(const std::vector<std::uint32_t>& newVertex, const std::vector<std::uint32_t>& newTet) {
  const std::size_t nv = numVertices(), slots = tetSlots();
  if (newVertex.size() != nv || newTet.size() != slots) throw MeshingError("TetMesh::renumber: sizes do not match");
  {
    std::vector<std::uint8_t> hit(std::max(nv, live_), 0);
    for (const std::uint32_t v : newVertex) {
      if (v >= nv || hit[v]) throw MeshingError("TetMesh::renumber: not a vertex permutation");
      hit[v] = 1;
    }
    std::fill(hit.begin(), hit.end(), 0);
    for (std::size_t t = 0; t < slots; ++t) {
      const bool alive = tv_[4 * t] != kFreeMark;
      if (alive != (newTet[t] != kNone) || (alive && (newTet[t] >= live_ || hit[newTet[t]])))
        throw MeshingError("TetMesh::renumber: not a permutation of the live tets");
      if (alive) hit[newTet[t]] = 1;
    }
  }
  // Each live record written once to its new place in fresh arrays (keeping the old
  // capacity reserved, so that later growth does not reallocate; pages never written cost
  // nothing): sequential reads, one pass.
  std::vector<std::uint32_t> tv, tn;
  std::vector<std::uint8_t> tf;
  tv.reserve(tv_.capacity());
  tn.reserve(tn_.capacity());
  tf.reserve(tf_.capacity());
  tv.resize(4 * live_);
  tn.resize(4 * live_);
  tf.resize(live_);
  for (std::size_t t = 0; t < slots; ++t) {
    const std::uint32_t n = newTet[t];
    if (n == kNone) continue;
    for (int i = 0; i < 4; ++i) {
      tv[4 * std::size_t{n} + i] = newVertex[tv_[4 * t + i]];
      const std::uint32_t c = tn_[4 * t + i];
      tn[4 * std::size_t{n} + i] = c == kNone ? kNone : 4 * newTet[c >> 2] + (c & 3u);
    }
    tf[n] = tf_[t];
  }
  tv_.swap(tv);
  tn_.swap(tn);
  tf_.swap(tf);
  tv = {}, tn = {}, tf = {};  // the old records, released before the vertex arrays are copied
  freeHead_ = kNone;
  std::vector<double> xyz(xyz_.size());
  std::vector<std::uint32_t> vtet(nv);
  for (std::size_t v = 0; v < nv; ++v) {
    const std::size_t w = newVertex[v];
    for (int k = 0; k < 3; ++k) xyz[3 * w + k] = xyz_[3 * v + k];
    vtet[w] = vtet_[v] == kNone ? kNone : newTet[vtet_[v]];
  }
  xyz_.swap(xyz);
  vtet_.swap(vtet);
}

void TetMesh::clear() {
  xyz_.clear();
  vtet_.clear();
  tv_.clear();
  tn_.clear();
  tf_.clear();
  freeHead_ = kNone;
  live_ = 0;
  certified_ = false;
}

std::size_t TetMesh::memoryBytes() const {
  return xyz_.capacity() * sizeof(double) + vtet_.capacity() * sizeof(std::uint32_t) +
         tv_.capacity() * sizeof(std::uint32_t) + tn_.capacity() * sizeof(std::uint32_t) +
         tf_.capacity() * sizeof(std::uint8_t);
}

}  // namespace aniso::del3d
