#include "mesher/volume/CoarseSolids.h"

namespace aniso {

std::vector<SizingSource> coarseSolidSources(const Model& model, const SurfaceMesh& surface,
                                             const std::vector<SolidOutcome>& solids) {
  std::vector<SizingSource> out;
  for (std::size_t s = 0; s < solids.size() && s < model.solids.size(); ++s) {
    const SolidOutcome& o = solids[s];
    if (o.status != SolidOutcome::Status::Ok || o.quality.meanRatio.count() == 0 ||
        !(o.quality.meanRatio.mean() < kCoarseMeanRatio))
      continue;
    std::vector<std::uint8_t> ofSolid(model.faces.size(), 0);
    std::vector<int> shells{model.solids[s].outerShell};
    shells.insert(shells.end(), model.solids[s].voidShells.begin(), model.solids[s].voidShells.end());
    for (const int sh : shells)
      if (sh >= 0 && sh < static_cast<int>(model.shells.size()))
        for (const FaceUse& u : model.shells[sh].faces)
          if (u.face >= 0 && u.face < static_cast<int>(ofSolid.size())) ofSolid[u.face] = 1;
    Box3 box;
    double length = 0;
    std::size_t faces = 0, triangles = 0;
    for (const std::uint8_t f : ofSolid) faces += f;
    for (std::size_t t = 0; t < surface.triangles.size(); ++t) {
      if (!ofSolid[surface.triangleFace[t]]) continue;
      ++triangles;
      const auto& tri = surface.triangles[t];
      for (int k = 0; k < 3; ++k) {
        box.add(surface.nodes[tri[k]]);
        length += (surface.nodes[tri[(k + 1) % 3]] - surface.nodes[tri[k]]).norm();
      }
    }
    if (triangles == 0 || static_cast<double>(triangles) > kCoarseTrianglesPerFace * static_cast<double>(faces)) continue;
    length /= static_cast<double>(3 * triangles);
    SizingSource src;
    src.kind = SizingSource::Kind::Box;
    src.a = box.lo - Vec3::Constant(length);
    src.b = box.hi + Vec3::Constant(length);
    src.metric = Metric3d::isotropic(kCoarseRefine * length);
    out.push_back(src);
  }
  return out;
}

}  // namespace aniso
