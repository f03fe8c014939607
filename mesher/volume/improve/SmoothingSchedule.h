#pragma once
// The order of a smoothing sweep (sec. 5.6.1) in blocks that several threads can smooth at
// once with the result of one thread. The vertices, in the given (Hilbert) order, are cut
// into blocks of kSmoothingBlock consecutive vertices (a compact region each: a block is
// smoothed in that order, as one thread would, Gauss-Seidel); two blocks conflict when a tet
// holds a vertex of each. The blocks are coloured greedily in order (each takes the first
// class none of its conflicting blocks is in), so the blocks of one class are independent: a
// move of v reads v's star (its tets' scores, its neighbours' positions and tensors) and
// writes only v's position, v's tensor and the scores of v's star, none of which another
// block of the class reads or writes. Classes run one after the other. The schedule depends
// on the mesh and the order only, never on the number of threads.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "mesher/delaunay3d/TetMesh.h"
#include "mesher/volume/improve/VertexTets.h"

namespace aniso::improve3d {

/// Vertices per block: large enough for a thread to work a while on one, small enough for
/// many blocks per class (a class holds about 1/10 of the blocks in 3D).
inline constexpr std::size_t kSmoothingBlock = 256;

struct SmoothingSchedule {
  std::vector<std::uint32_t> vertices;   ///< the order given
  std::vector<std::size_t> blockStart;   ///< per block and the end: block k is [blockStart[k], blockStart[k+1])
  std::vector<std::uint32_t> blocks;     ///< block indices, class by class, in block order within a class
  std::vector<std::size_t> classStart;   ///< per class and the end, into `blocks`
  std::size_t classes() const { return classStart.empty() ? 0 : classStart.size() - 1; }
};

/// The schedule of the vertices of `order` (vertex indices, each once); blockSize > 0.
SmoothingSchedule smoothingSchedule(const del3d::TetMesh& mesh, const VertexTets& incidence,
                                    const std::vector<std::uint32_t>& order, std::size_t blockSize = kSmoothingBlock);

/// True when every vertex of the schedule is in one block of one class and no tet of `mesh`
/// holds vertices of two different blocks of one class (for tests).
bool scheduleIndependent(const del3d::TetMesh& mesh, const SmoothingSchedule& schedule);

}  // namespace aniso::improve3d
