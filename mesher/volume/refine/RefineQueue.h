#pragma once
// The refinement queue of alg. 5.3: tets with q(K) < q_t, worst first. A binary heap over
// millions of entries spends most of its time in cache misses (docs/measurements.md), so
// this is a bucket queue: q ∈ [0, q_t) is cut into kBuckets equal buckets (width q_t /
// kBuckets ≈ 0.009), pop() takes from the lowest non-empty bucket, last in first out within
// a bucket (the tets made by the latest insertion, which lie together). Worst first holds
// to the bucket width; push and pop are O(1). Deterministic.
// Lazy deletion: each tet slot carries a stamp that changes whenever the slot gets a new
// tet; an entry whose stamp differs, or whose slot is free, is stale and skipped by pop().
// Entries are 12 bytes; compactIfGrown() drops stale ones when the queue has doubled.
#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "mesher/delaunay3d/TetMesh.h"

namespace aniso::refine3d {

class RefineQueue {
 public:
  struct Entry {
    float q;
    std::uint32_t tet;
    std::uint32_t stamp;
  };
  static constexpr int kBuckets = 64;

  /// Entries with q ≥ threshold go to the last bucket.
  explicit RefineQueue(double threshold) : scale_(kBuckets / threshold) {}

  /// The slot holds a new tet: entries pushed for the slot before are now stale.
  void renew(del3d::TetId t) {
    if (t.index >= stamp_.size()) stamp_.resize(std::size_t{t.index} + 1, 0);  // geometric growth beyond reserve()
    ++stamp_[t.index];
  }
  /// Room for the stamps of this many tet slots (untouched memory until used).
  void reserve(std::size_t slots) { stamp_.reserve(slots); }
  void push(del3d::TetId t, double q) {
    const int b = std::clamp(static_cast<int>(q * scale_), 0, kBuckets - 1);
    buckets_[b].push_back({static_cast<float>(q), t.index, stampOf(t)});
    lowest_ = std::min(lowest_, b);
    ++size_;
  }
  /// The worst live, current entry (removed from the queue); false when none is left.
  bool pop(const del3d::TetMesh& mesh, Entry& out) {
    for (; lowest_ < kBuckets; ++lowest_) {
      std::vector<Entry>& b = buckets_[lowest_];
      while (!b.empty()) {
        out = b.back();
        b.pop_back();
        --size_;
        if (current(mesh, out)) return true;
      }
    }
    return false;
  }
  /// Whether a popped entry still describes its slot's tet.
  bool current(const del3d::TetMesh& mesh, const Entry& e) const {
    const del3d::TetId t(e.tet);
    return mesh.isAlive(t) && stampOf(t) == e.stamp;
  }
  /// Returns the memory of buckets that have drained to a quarter of their capacity (the
  /// queue's largest size comes mid-refinement; its buckets would otherwise hold that
  /// memory up to the end, the peak of the mesh). O(kBuckets).
  void releaseDrained() {
    for (std::vector<Entry>& b : buckets_)
      if (b.capacity() > 4 * b.size() + kMinRelease) b.shrink_to_fit();
  }
  /// Entries held, stale ones included.
  std::size_t size() const { return size_; }
  /// Drops the stale entries (order within a bucket kept) once they may be the majority:
  /// when the queue has doubled since the last compaction. Amortized O(1) per push; bounds
  /// the memory of entries of tets long destroyed (the peak of the refinement).
  void compactIfGrown(const del3d::TetMesh& mesh) {
    if (size_ < std::max<std::size_t>(2 * compacted_, kMinCompaction)) return;
    size_ = 0;
    for (std::vector<Entry>& b : buckets_) {
      std::erase_if(b, [&](const Entry& e) { return !current(mesh, e); });
      if (b.capacity() > 2 * b.size() + 64) b.shrink_to_fit();
      size_ += b.size();
    }
    compacted_ = size_;
  }

 private:
  std::uint32_t stampOf(del3d::TetId t) const { return t.index < stamp_.size() ? stamp_[t.index] : 0u; }

  double scale_;
  std::array<std::vector<Entry>, kBuckets> buckets_;
  int lowest_ = kBuckets;
  std::size_t size_ = 0;
  std::size_t compacted_ = 0;  // size after the last compaction
  std::vector<std::uint32_t> stamp_;
  static constexpr std::size_t kMinCompaction = 1 << 16;
  static constexpr std::size_t kMinRelease = 1 << 12;
};

}  // namespace aniso::refine3d
