#include "mesher/volume/CoarseSolids.h"

#include <algorithm>

namespace aniso {
namespace {

/// Solid s's boundary as meshed: its faces (sorted, embedded ones included), the box of
/// its triangles and their mean edge length.
struct MeshedBoundary {
  std::vector<int> faces;
  Box3 box;
  double meanEdge = 0;
  std::size_t triangles = 0;
};

MeshedBoundary boundaryOf(const Model& model, const SurfaceMesh& surface, int s) {
  MeshedBoundary b;
  b.faces = model.solidBoundaryFaces(s);
  std::vector<std::uint8_t> ofSolid(model.faces.size(), 0);
  for (const int f : b.faces)
    if (f >= 0 && f < static_cast<int>(ofSolid.size())) ofSolid[static_cast<std::size_t>(f)] = 1;
  double length = 0;
  for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
    if (!ofSolid[static_cast<std::size_t>(surface.triangleFace[t])]) continue;
    ++b.triangles;
    const auto& tri = surface.triangles[t];
    for (int k = 0; k < 3; ++k) {
      b.box.add(surface.nodes[tri[k]]);
      length += (surface.nodes[tri[(k + 1) % 3]] - surface.nodes[tri[k]]).norm();
    }
  }
  if (b.triangles > 0) b.meanEdge = length / static_cast<double>(3 * b.triangles);
  return b;
}

/// A box over the boundary grown by its mean edge, sizing the solid's faces only.
SizingSource sourceOver(MeshedBoundary&& b, double size) {
  SizingSource src;
  src.kind = SizingSource::Kind::Box;
  src.a = b.box.lo - Vec3::Constant(b.meanEdge);
  src.b = b.box.hi + Vec3::Constant(b.meanEdge);
  src.metric = Metric3d::isotropic(size);
  src.faces = std::move(b.faces);
  return src;
}

}  // namespace

std::vector<SizingSource> coarseSolidSources(const Model& model, const SurfaceMesh& surface,
                                             const std::vector<SolidOutcome>& solids) {
  std::vector<SizingSource> out;
  for (std::size_t s = 0; s < solids.size() && s < model.solids.size(); ++s) {
    const SolidOutcome& o = solids[s];
    if (o.status != SolidOutcome::Status::Ok || o.quality.meanRatio.count() == 0 ||
        !(o.quality.meanRatio.mean() < kCoarseMeanRatio))
      continue;
    MeshedBoundary b = boundaryOf(model, surface, static_cast<int>(s));
    if (b.triangles == 0 || static_cast<double>(b.triangles) > kCoarseTrianglesPerFace * static_cast<double>(b.faces.size()))
      continue;
    const double size = kCoarseRefine * b.meanEdge;
    out.push_back(sourceOver(std::move(b), size));
  }
  return out;
}

std::vector<int> failedSolids(const std::vector<SolidOutcome>& solids) {
  std::vector<int> out;
  for (std::size_t s = 0; s < solids.size(); ++s)
    if (solids[s].status == SolidOutcome::Status::Failed && !solids[s].leftOutBySurface())
      out.push_back(static_cast<int>(s));
  return out;
}

std::vector<SizingSource> failedSolidSources(const Model& model, const SurfaceMesh& surface,
                                             const std::vector<SolidOutcome>& solids) {
  std::vector<SizingSource> out;
  for (const int s : failedSolids(solids)) {
    if (s >= static_cast<int>(model.solids.size())) continue;
    MeshedBoundary b = boundaryOf(model, surface, s);
    if (b.triangles == 0) continue;
    const double size = kFailedRefine * b.meanEdge;
    out.push_back(sourceOver(std::move(b), size));
  }
  return out;
}

}  // namespace aniso
