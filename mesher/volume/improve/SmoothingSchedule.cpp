#include "mesher/volume/improve/SmoothingSchedule.h"

#include <algorithm>
#include <limits>

namespace aniso::improve3d {

namespace {
constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
}

SmoothingSchedule smoothingSchedule(const del3d::TetMesh& mesh, const VertexTets& incidence,
                                    const std::vector<std::uint32_t>& order, std::size_t blockSize) {
  SmoothingSchedule s;
  s.vertices = order;
  const std::size_t nb = (order.size() + blockSize - 1) / blockSize;
  std::vector<std::uint32_t> blockOf(mesh.numVertices(), kNone);
  for (std::size_t k = 0; k <= nb; ++k) s.blockStart.push_back(std::min(k * blockSize, order.size()));
  for (std::size_t i = 0; i < order.size(); ++i) blockOf[order[i]] = static_cast<std::uint32_t>(i / blockSize);
  std::vector<std::uint32_t> cls(nb, kNone);
  std::vector<std::uint32_t> takenBy;  // per class: the last block a conflicting block of which holds it
  std::vector<std::size_t> count;
  for (std::uint32_t b = 0; b < nb; ++b) {
    for (std::size_t i = s.blockStart[b]; i < s.blockStart[b + 1]; ++i)
      for (const std::uint32_t t : incidence.of(del3d::VertexId(order[i]))) {
        const std::uint32_t* tv = mesh.tetVertices(del3d::TetId(t));
        for (int k = 0; k < 4; ++k) {
          const std::uint32_t other = blockOf[tv[k]];
          if (other != kNone && other != b && cls[other] != kNone) takenBy[cls[other]] = b;
        }
      }
    std::uint32_t c = 0;
    while (c < takenBy.size() && takenBy[c] == b) ++c;
    if (c == takenBy.size()) {
      takenBy.push_back(kNone);
      count.push_back(0);
    }
    cls[b] = c;
    ++count[c];
  }
  s.classStart.assign(count.size() + 1, 0);
  for (std::size_t c = 0; c < count.size(); ++c) s.classStart[c + 1] = s.classStart[c] + count[c];
  s.blocks.resize(nb);
  std::vector<std::size_t> next(s.classStart.begin(), s.classStart.end() - 1);
  for (std::uint32_t b = 0; b < nb; ++b) s.blocks[next[cls[b]]++] = b;
  return s;
}

bool scheduleIndependent(const del3d::TetMesh& mesh, const SmoothingSchedule& schedule) {
  std::vector<std::uint32_t> blockOf(mesh.numVertices(), kNone), classOf(mesh.numVertices(), kNone);
  std::vector<char> blockSeen(schedule.blocks.size(), 0);
  for (std::size_t c = 0; c < schedule.classes(); ++c)
    for (std::size_t k = schedule.classStart[c]; k < schedule.classStart[c + 1]; ++k) {
      const std::uint32_t b = schedule.blocks[k];
      if (b + 1 >= schedule.blockStart.size() || blockSeen[b]) return false;  // a block twice
      blockSeen[b] = 1;
      for (std::size_t i = schedule.blockStart[b]; i < schedule.blockStart[b + 1]; ++i) {
        const std::uint32_t v = schedule.vertices[i];
        if (v >= mesh.numVertices() || blockOf[v] != kNone) return false;  // a vertex twice
        blockOf[v] = b;
        classOf[v] = static_cast<std::uint32_t>(c);
      }
    }
  if (std::find(blockSeen.begin(), blockSeen.end(), 0) != blockSeen.end()) return false;
  for (std::uint32_t t = 0; t < mesh.tetSlots(); ++t) {
    if (!mesh.isAlive(del3d::TetId(t))) continue;
    const std::uint32_t* tv = mesh.tetVertices(del3d::TetId(t));
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        if (classOf[tv[a]] != kNone && classOf[tv[a]] == classOf[tv[b]] && blockOf[tv[a]] != blockOf[tv[b]])
          return false;
  }
  return true;
}

}  // namespace aniso::improve3d
