// anisomesh sizing FILE [--face N] -o cs.vtu: the initial control space of the faces (thesis
// alg. 3.2) as a VTU file, so that a user can see the metric the mesher will follow.
// With --face N: that face's control space in its parametric plane (u, v, 0). Without:
// every face, its control-space cells mapped onto the surface in 3D, with the metric's
// main directions and lengths expressed in space (cell data "face" = CAD face id).
#include <Eigen/Geometry>
#include <Eigen/LU>

#include <filesystem>

#include "io/ControlSpaceVtu.h"
#include "io/SizingFile.h"
#include "mesher/core/Error.h"
#include "mesher/core/FileExtension.h"
#include "mesher/sizing/FaceControlSpace.h"
#include "mesher/sizing/VolumeChordBound.h"
#include "tools/cli/Commands.h"
#include "tools/app/ModelInput.h"

namespace aniso::cli {
namespace {

/// Appends the grid of one face, mapped to 3D, to `all`.
void appendFaceIn3d(const ControlSpaceGrid& g, const ParametricSurface& s, int faceId, ControlSpaceGrid& all,
                    std::vector<int>& cellFace) {
  const int base = static_cast<int>(all.points.size());
  for (size_t i = 0; i < g.points.size(); ++i) {
    const Vec2 uv(g.points[i].x(), g.points[i].y());
    const SurfaceD1 d = s.d1(uv);
    all.points.push_back(d.p);
    Eigen::Matrix<double, 3, 2> j;
    j.col(0) = d.pu;
    j.col(1) = d.pv;
    const Mat2 mp = g.parameterization.empty() ? Mat2::Identity() : Mat2(g.parameterization[i].topLeftCorner<2, 2>());
    // A unit direction e of S^R is the parametric vector M_p⁻¹ e, i.e. J M_p⁻¹ e in space.
    const Eigen::Matrix<double, 3, 2> toSpace = j * mp.inverse();
    Mat3 dirs = Mat3::Zero(), tensor = Mat3::Zero();
    Vec3 lengths = Vec3::Zero();
    for (int k = 0; k < 2; ++k) {
      const Vec2 e = g.directions[i].block<2, 1>(0, k);
      Vec3 e3 = toSpace * e;
      if (e3.norm() > 0) e3.normalize();
      dirs.col(k) = e3;
      lengths[k] = g.lengths[i][k];
      tensor += e3 * e3.transpose() / lengths[k];
    }
    dirs.col(2) = dirs.col(0).cross(dirs.col(1));
    all.metric.push_back(tensor);
    all.lengths.push_back(lengths);
    all.directions.push_back(dirs);
  }
  for (int c : g.cells) all.cells.push_back(base + c);
  for (int l : g.cellLevel) {
    all.cellLevel.push_back(l);
    cellFace.push_back(faceId);
  }
}

}  // namespace

int runSizing(const SizingArgs& args) {
  if (lowerExtension(args.output) != ".vtu")
    throw InputError(args.output + ": the control space is written as .vtu");
  const std::string bad = args.params.check();
  if (!bad.empty()) throw InputError(args.file + ": " + bad);
  const UserSizing user = args.sizingFile.empty() ? UserSizing{} : io::readSizingFile(args.sizingFile);
  const app::ModelInput in = app::loadModel(args.file, args.fragment);
  const int nf = static_cast<int>(in.model.faces.size());
  if (nf == 0) throw InputError(args.file + ": the model has no faces");
  if (args.face != 0 && (args.face < 1 || args.face > nf))
    throw InputError(args.file + ": --face " + std::to_string(args.face) + " out of range (the model has " +
                     std::to_string(nf) + " faces)");
  const std::unique_ptr<ControlSpace2d> analytic = app::analyticControlSpace(in);

  FaceSizingInput fin;
  fin.model = &in.model;
  fin.params = args.params;
  fin.analytic = analytic.get();
  fin.user = &user;
  fin.chordDeviation = volumeChordDeviation(in.model, args.params.chordDeviationRel * in.model.diagonal());
  if (args.face != 0) {
    fin.face = args.face - 1;
    io::writeControlSpaceVtu(buildFaceControlSpace(fin)->grid(), args.output);
    return 0;
  }
  ControlSpaceGrid all;
  all.dim = 2;
  all.cellSize = 4;
  std::vector<int> cellFace;
  for (int f = 0; f < nf; ++f) {
    if (!in.model.faces[f].surface) continue;  // unusable (Model::check): no sizes to show
    fin.face = f;
    const ControlSpaceGrid g = buildFaceControlSpace(fin)->grid();
    appendFaceIn3d(g, *in.model.faces[f].surface, f + 1, all, cellFace);
  }
  io::writeControlSpaceVtu(all, args.output, &cellFace);
  return 0;
}

}  // namespace aniso::cli
