#pragma once
// Items grouped by a node index: a counting sort, linear in items + nodes and stable (the
// items of a bucket keep their order). The mesh checks group edge uses by their smaller end
// with it and sort each bucket's few items, instead of sorting every edge use of the mesh
// (a global sort of the edge uses was a tenth of a whole run on large meshes).
#include <cstddef>
#include <span>
#include <vector>

namespace aniso {

template <class Item>
struct NodeBuckets {
  /// The items of node a are items[start[a], start[a + 1]).
  std::vector<std::size_t> start;
  std::vector<Item> items;

  std::size_t nodes() const { return start.empty() ? 0 : start.size() - 1; }
  std::span<Item> bucket(std::size_t a) { return {items.data() + start[a], start[a + 1] - start[a]}; }
};

/// The items by nodeOf(item), which must lie in [0, numNodes).
template <class Item, class NodeOf>
NodeBuckets<Item> bucketByNode(std::span<const Item> items, std::size_t numNodes, NodeOf nodeOf) {
  NodeBuckets<Item> b;
  b.start.assign(numNodes + 2, 0);
  for (const Item& it : items) ++b.start[static_cast<std::size_t>(nodeOf(it)) + 2];
  for (std::size_t i = 2; i < b.start.size(); ++i) b.start[i] += b.start[i - 1];
  b.items.resize(items.size());
  for (const Item& it : items) b.items[b.start[static_cast<std::size_t>(nodeOf(it)) + 1]++] = it;
  b.start.pop_back();
  return b;
}

}  // namespace aniso
