#pragma once
// VertexTensors — the per-vertex metric store of the refinement (thesis sec. 5.5): the
// control space's transformation tensor at each vertex, queried once per vertex, so that the
// metric of a tet (the mean of its four vertices' tensors, VolumeRefinement.h) costs no
// control-space call. An isotropic tensor s·I (uniform or isotropic sizing: the common case)
// is kept as its scale s alone (8 bytes instead of a 72-byte matrix); a tet whose four
// vertices are isotropic has the scalar metric s̄·I with s̄ their mean — the fast path of
// the refinement, where q(K) and the edge lengths are Euclidean ones times s̄.
// Not thread-safe for writes.
#include <cstdint>
#include <vector>

#include "mesher/control/ControlSpace3d.h"
#include "mesher/delaunay3d/TetMesh.h"
#include "mesher/metric/IsotropicTensor.h"

namespace aniso::refine3d {

/// The tensors of VertexTensors handed on (VertexTensors::release): per vertex the scale of
/// an isotropic s·I, or 0 and the index of its matrix in `aniso`.
struct VertexTensorTable {
  std::vector<double> scale;
  std::vector<std::uint32_t> index;
  std::vector<Mat3> aniso;
  std::size_t size() const { return scale.size(); }
  Mat3 at(std::size_t v) const { return scale[v] > 0 ? Mat3(scale[v] * Mat3::Identity()) : aniso[index[v]]; }
  /// Vertex v becomes newVertex[v] (a permutation of the ids, as TetMesh::renumber).
  void renumber(const std::vector<std::uint32_t>& newVertex);
};

class VertexTensors {
 public:
  VertexTensors(const del3d::TetMesh& mesh, const ControlSpace3d& cs) : mesh_(mesh), cs_(cs) { sync(); }
  /// Queries the tensors of the vertices added to the mesh since the last call (a vertex
  /// in no tet gets the identity).
  void sync();
  /// Records m as the tensor of v, the vertex just added (its metric already queried).
  void add(del3d::VertexId v, const Mat3& m);

  bool isotropic(del3d::VertexId v) const { return t_.scale[v.index] > 0; }
  /// The scale s of an isotropic tensor s·I (0 for an anisotropic one).
  double scale(del3d::VertexId v) const { return t_.scale[v.index]; }
  /// The tensor of v.
  Mat3 at(del3d::VertexId v) const { return t_.at(v.index); }
  /// True, with s̄ the mean scale, when the four vertices v[0..3] are isotropic.
  bool tetScale(const std::uint32_t* v, double& s) const {
    const double a = t_.scale[v[0]], b = t_.scale[v[1]], c = t_.scale[v[2]], d = t_.scale[v[3]];
    s = 0.25 * (a + b + c + d);
    return a > 0 && b > 0 && c > 0 && d > 0;
  }
  /// The mean of the four vertices' tensors.
  Mat3 tetMetric(const std::uint32_t* v) const;
  /// The metric of the tet by eq. 2.18, the control space's own interpolation
  /// (MetricInterpolation.h): the inverse of the mean of the four vertices' length tensors
  /// (inverse transformation tensors). Where the size grades, the mean of the tensors is
  /// ruled by the finest vertex (a harmonic mean of the sizes) and measures the tet finer
  /// than the control space at its centroid; eq. 2.18 averages the sizes.
  Mat3 tetLengthMetric(const std::uint32_t* v) const;
  /// True, with s = 4 / Σ 1/s_i (eq. 2.18 for tensors s_i·I), when the four vertices are
  /// isotropic.
  bool tetLengthScale(const std::uint32_t* v, double& s) const {
    const double a = t_.scale[v[0]], b = t_.scale[v[1]], c = t_.scale[v[2]], d = t_.scale[v[3]];
    if (!(a > 0 && b > 0 && c > 0 && d > 0)) return false;
    s = 4.0 / (1.0 / a + 1.0 / b + 1.0 / c + 1.0 / d);
    return true;
  }
  /// Eq. 2.18 at the midpoint of the edge (a, b).
  Mat3 edgeLengthMetric(del3d::VertexId a, del3d::VertexId b) const;
  /// Bytes held (capacities).
  std::size_t memoryBytes() const;
  /// Moves the tensors out (this object is empty afterwards).
  VertexTensorTable release() { return std::move(t_); }

 private:
  void store(std::size_t v, const Mat3& m);

  const del3d::TetMesh& mesh_;
  const ControlSpace3d& cs_;
  VertexTensorTable t_;
};

/// Eq. 2.18 at the midpoint of an edge whose ends have the isotropic scales a and b.
inline double edgeLengthScale(double a, double b) { return 2.0 / (1.0 / a + 1.0 / b); }

/// Eq. 6.2 over the live tets of `mesh` with M_K the mean of the vertices' tensors in vt
/// (predictTetCount of VolumeRefinement.h; defined there).
double predictTetCount(const del3d::TetMesh& mesh, const VertexTensors& vt);

}  // namespace aniso::refine3d
