#pragma once
// The refinement heap of alg. 5.3: tets with q(K) < q_t, worst on top, ordered by
// (q, tet slot) so the order is deterministic. Lazy deletion: each tet slot carries a
// stamp that changes whenever the slot gets a new tet; an entry whose stamp differs, or
// whose slot is free, is stale and skipped by pop(). Entries are 12 bytes.
#include <cstdint>
#include <queue>
#include <vector>

#include "mesher/delaunay3d/TetMesh.h"

namespace aniso::refine3d {

class RefineHeap {
 public:
  struct Entry {
    float q;
    std::uint32_t tet;
    std::uint32_t stamp;
  };

  /// The slot holds a new tet: entries pushed for the slot before are now stale.
  void renew(del3d::TetId t) {
    if (t.index >= stamp_.size()) stamp_.resize(std::size_t{t.index} + 1 + stamp_.size() / 2, 0);
    ++stamp_[t.index];
  }
  void push(del3d::TetId t, double q) { heap_.push({static_cast<float>(q), t.index, stampOf(t)}); }
  /// The worst live, current entry (removed from the heap); false when none is left.
  bool pop(const del3d::TetMesh& mesh, Entry& out) {
    while (!heap_.empty()) {
      out = heap_.top();
      heap_.pop();
      if (current(mesh, out)) return true;
    }
    return false;
  }
  /// Whether a popped entry still describes its slot's tet.
  bool current(const del3d::TetMesh& mesh, const Entry& e) const {
    const del3d::TetId t(e.tet);
    return mesh.isAlive(t) && stampOf(t) == e.stamp;
  }
  std::size_t size() const { return heap_.size(); }
  std::size_t memoryBytes() const { return heap_.size() * sizeof(Entry) + stamp_.capacity() * sizeof(std::uint32_t); }

 private:
  struct Worse {  // priority_queue keeps the "largest" on top: the smallest q
    bool operator()(const Entry& x, const Entry& y) const { return x.q > y.q || (x.q == y.q && x.tet > y.tet); }
  };
  std::uint32_t stampOf(del3d::TetId t) const { return t.index < stamp_.size() ? stamp_[t.index] : 0u; }

  std::priority_queue<Entry, std::vector<Entry>, Worse> heap_;
  std::vector<std::uint32_t> stamp_;
};

}  // namespace aniso::refine3d
