#pragma once
// KeySet — a set of 64-bit keys with open addressing (linear probing, power-of-two table,
// load at most 1/2), for hot loops that dedupe many small integer keys (mesh entities by
// vertex or face codes) where std::set / std::unordered_set spend their time allocating
// nodes. Keys are any value except kEmpty. clear() keeps the table, so a reused set does
// not allocate again. Iteration order is not offered (results never depend on the hash).
#include <algorithm>
#include <cstdint>
#include <vector>

namespace aniso {

class KeySet {
 public:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};

  /// Inserts `key` (not kEmpty); true when it was not there yet.
  bool insert(std::uint64_t key) {
    if (2 * (size_ + 1) > slots_.size()) grow();
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = hash(key) & mask;; i = (i + 1) & mask) {  // ends: the table is at most half full
      if (slots_[i] == key) return false;
      if (slots_[i] == kEmpty) {
        slots_[i] = key;
        ++size_;
        return true;
      }
    }
  }

  std::size_t size() const { return size_; }
  void clear() {
    if (size_ == 0) return;
    std::fill(slots_.begin(), slots_.end(), kEmpty);
    size_ = 0;
  }

 private:
  static std::uint64_t hash(std::uint64_t k) {  // splitmix64 finaliser
    k ^= k >> 30;
    k *= 0xbf58476d1ce4e5b9ull;
    k ^= k >> 27;
    k *= 0x94d049bb133111ebull;
    return k ^ (k >> 31);
  }
  void grow() {
    std::vector<std::uint64_t> old(slots_.empty() ? 64 : 2 * slots_.size(), kEmpty);
    old.swap(slots_);
    size_ = 0;
    for (const std::uint64_t k : old)
      if (k != kEmpty) insert(k);
  }

  std::vector<std::uint64_t> slots_;
  std::size_t size_ = 0;
};

}  // namespace aniso
