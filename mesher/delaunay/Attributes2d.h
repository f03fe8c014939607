#pragma once
// Per-triangle and per-vertex attribute arrays kept beside the topology (STYLE.md §3,
// OpenMesh properties): each attribute is its own std::vector, indexed by the handle,
// grown automatically when the triangulation gets new slots or vertices. Values of a
// triangle slot that is freed and reused are NOT reset: operators that create triangles
// document what the caller has to recompute (e.g. quality).
//
// Lifetime: an attribute registers with the triangulation on construction and unregisters
// on destruction. When the triangulation is moved it follows the new object; when the
// triangulation is destroyed first, the attribute keeps its values but no longer grows.
// Attributes are not copied with a triangulation. Not copyable or movable themselves.
#include <algorithm>
#include <cstddef>
#include <type_traits>
#include <vector>

#include "mesher/delaunay/Triangulation2d.h"

namespace aniso::del2d {

namespace detail {
template <class T, class Handle, bool PerTriangle>
class AttributeArray final : public AttributeSlot {
  static_assert(!std::is_same_v<T, bool>, "use std::uint8_t: std::vector<bool> has no T&");

 public:
  explicit AttributeArray(Triangulation2d& tri, T init = T()) : tri_(&tri), init_(init) {
    if constexpr (PerTriangle) tri.attachTriangleAttribute(this);
    else tri.attachVertexAttribute(this);
  }
  ~AttributeArray() override {
    if (tri_ != nullptr) tri_->detachAttribute(this);
  }
  AttributeArray(const AttributeArray&) = delete;
  AttributeArray& operator=(const AttributeArray&) = delete;

  T& operator[](Handle h) { return data_[h.index]; }
  const T& operator[](Handle h) const { return data_[h.index]; }
  std::size_t size() const { return data_.size(); }
  std::vector<T>& data() { return data_; }
  const std::vector<T>& data() const { return data_; }
  /// Sets every entry to v.
  void fill(const T& v) { std::fill(data_.begin(), data_.end(), v); }

  void grow(std::size_t n) override {
    if (data_.size() < n) data_.resize(n, init_);
  }
  void rebind(Triangulation2d* t) override { tri_ = t; }

 private:
  Triangulation2d* tri_;
  T init_;
  std::vector<T> data_;
};
}  // namespace detail

/// Value per triangle slot (new slots get `init`).
template <class T>
using TriangleAttribute = detail::AttributeArray<T, TriId, true>;
/// Value per vertex (new vertices get `init`).
template <class T>
using VertexAttribute = detail::AttributeArray<T, VertexId, false>;

}  // namespace aniso::del2d
