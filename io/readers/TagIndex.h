#pragma once
// TagIndex — file ids (MSH node tags, INP node and element numbers) to 0-based indices.
// A dense table when the ids are compact, a hash map otherwise.
#include <unordered_map>
#include <vector>

namespace aniso::io {

class TagIndex {
 public:
  /// `tags[i]` is the id of index i. False when an id repeats (the first one is kept).
  bool build(const std::vector<long long>& tags) {
    dense_.clear();
    sparse_.clear();
    sparse_mode_ = false;
    bool unique = true;
    if (tags.empty()) return true;
    long long lo = tags[0], hi = tags[0];
    for (long long t : tags) {
      lo = t < lo ? t : lo;
      hi = t > hi ? t : hi;
    }
    if (lo >= 0 && hi < 4 * static_cast<long long>(tags.size()) + 1024) {
      dense_.assign(static_cast<std::size_t>(hi) + 1, -1);
      for (std::size_t i = 0; i < tags.size(); ++i) {
        int& slot = dense_[static_cast<std::size_t>(tags[i])];
        if (slot >= 0) unique = false; else slot = static_cast<int>(i);
      }
      return unique;
    }
    for (std::size_t i = 0; i < tags.size(); ++i) unique = sparse_.emplace(tags[i], static_cast<int>(i)).second && unique;
    sparse_mode_ = true;
    return unique;
  }
  /// The index of an id, −1 when unknown.
  int find(long long tag) const {
    if (!sparse_mode_) return tag >= 0 && tag < static_cast<long long>(dense_.size()) ? dense_[tag] : -1;
    const auto it = sparse_.find(tag);
    return it == sparse_.end() ? -1 : it->second;
  }

 private:
  std::vector<int> dense_;
  std::unordered_map<long long, int> sparse_;
  bool sparse_mode_ = false;
};

}  // namespace aniso::io
