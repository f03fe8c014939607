#pragma once
// The per-point tensors of a ControlSpaceGrid (see ControlSpaceGrid.h for the layout),
// shared by the grid() exports of TreeControlSpace<D> and BackgroundMesh<D>.
//   setGridTensors<D>(g, metric)        metric, lengths and directions of every point from
//                                       its M_s (2D in the upper-left block, the rest 0,
//                                       third direction (0, 0, 1));
//   setGridParameterization<D>(g, aux)  M_p of every point in the upper-left block.
// Both size the arrays to the number of tensors given.
#include <vector>

#include "mesher/control/ControlSpaceGrid.h"
#include "mesher/metric/Metric.h"

namespace aniso {

template <int D>
void setGridTensors(ControlSpaceGrid& g, const std::vector<Metric<D>>& metric) {
  const std::size_t nv = metric.size();
  g.metric.assign(nv, Mat3::Zero());
  g.lengths.assign(nv, Vec3::Zero());
  g.directions.assign(nv, Mat3::Identity());
  for (std::size_t v = 0; v < nv; ++v) {
    const MetricAxes<D> a = metric[v].axes();
    g.metric[v].template topLeftCorner<D, D>() = metric[v].matrix();
    g.lengths[v].template head<D>() = a.lengths;
    g.directions[v].template topLeftCorner<D, D>() = a.directions;
  }
}

template <int D>
void setGridParameterization(ControlSpaceGrid& g, const std::vector<Eigen::Matrix<double, D, D>>& aux) {
  g.parameterization.assign(aux.size(), Mat3::Zero());
  for (std::size_t v = 0; v < aux.size(); ++v) g.parameterization[v].template topLeftCorner<D, D>() = aux[v];
}

}  // namespace aniso
