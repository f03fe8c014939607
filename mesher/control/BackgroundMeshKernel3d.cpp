// BackgroundMeshKernel<3>: location, insertion, stars and tetrahedron geometry of the
// background mesh of volume meshing.
#include "mesher/control/BackgroundMeshKernel3d.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <bit>

#include "mesher/delaunay3d/EdgeRing.h"
#include "mesher/delaunay3d/EnclosingBox.h"
#include "mesher/delaunay3d/Validate.h"
#include "mesher/predicates/Predicates.h"

namespace aniso {

using del3d::TetId;
using del3d::VertexId;

namespace {

/// Vertices per seed-octree leaf (all compared per query: the nearest leaves a walk of a
/// step or two).
constexpr std::uint32_t kSeedLeaf = 8;

}  // namespace

BackgroundMeshKernel<3>::BackgroundMeshKernel(const Box3& bounds, const BackgroundMeshOptions& options)
    : mesh_(std::make_unique<del3d::TetMesh>()) {
  const del3d::EnclosingBox box = del3d::createEnclosingBox(*mesh_, bounds, options.boxMargin);
  inserter_ = std::make_unique<del3d::Inserter>(*mesh_);
  seeds_ = std::make_unique<VertexSeedOctree>(box.box, kSeedLeaf);
  for (std::uint32_t v = 0; v < mesh_->numVertices(); ++v) seeds_->insert(v, mesh_->point(VertexId(v)));
}

TetId BackgroundMeshKernel<3>::locate(const Vec3& p, TetId start, std::uint32_t& rng) const {
  if (!start.valid() || !mesh_->isAlive(start)) start = mesh_->vertexTet(VertexId(seeds_->nearest(p)));
  for (std::uint32_t k = 0; !start.valid() && k < mesh_->tetSlots(); ++k)
    if (mesh_->isAlive(TetId(k))) start = TetId(k);
  const del3d::LocateResult r = del3d::locate(*mesh_, p.data(), start, rng);
  if (r.status == del3d::LocateStatus::Outside || !r.tet.valid()) return TetId();
  // On a face or an edge several tetrahedra contain p: take the one with the smallest
  // slot, so that the field (A_t, A_s) does not depend on where the walk came from. On a
  // vertex every set holds the vertex and the ε_M shortcut answers.
  TetId t = r.tet;
  if (r.status == del3d::LocateStatus::OnFace) {
    const TetId u = mesh_->neighbour(t, std::countr_zero(r.zeroFaces));
    if (u.valid() && u.index < t.index) t = u;
  } else if (r.status == del3d::LocateStatus::OnEdge) {
    int ends[2], n = 0;
    for (int i = 0; i < 4; ++i)
      if (!((r.zeroFaces >> i) & 1u)) ends[n++] = i;
    std::array<TetId, 64> ring;
    std::array<VertexId, 64> apex;
    const int m = del3d::closedEdgeRing(*mesh_, r.tet, ends[0], ends[1], ring, apex);
    for (int k = 0; k < m; ++k)
      if (ring[k].index < t.index) t = ring[k];
  }
  return t;
}

KernelInsertion BackgroundMeshKernel<3>::insert(const Vec3& p, TetId near) {
  const del3d::InsertResult r = inserter_->insert(p, near.valid() && mesh_->isAlive(near) ? near : TetId());
  KernelInsertion res;
  if (r.status == del3d::InsertStatus::Duplicate || r.status == del3d::InsertStatus::Inserted) {
    res.vertex = static_cast<int>(r.vertex.index);
    res.created = r.status == del3d::InsertStatus::Inserted;
  }
  if (res.created) seeds_->insert(r.vertex.index, p);
  return res;
}

void BackgroundMeshKernel<3>::appendCreated(int, std::vector<TetId>& out) const {
  const auto fresh = inserter_->newTets();
  out.insert(out.end(), fresh.begin(), fresh.end());
}

void BackgroundMeshKernel<3>::appendStar(int v, std::vector<TetId>& out) const {
  const VertexId vid(static_cast<std::uint32_t>(v));
  const TetId first = mesh_->vertexTet(vid);
  if (!first.valid()) return;
  const std::size_t begin = out.size();
  out.push_back(first);
  for (std::size_t k = begin; k < out.size(); ++k) {
    const TetId t = out[k];
    const int own = mesh_->localIndex(t, vid);
    for (int j = 0; j < 4; ++j) {
      if (j == own) continue;  // the faces through v are those opposite its other vertices
      const TetId u = mesh_->neighbour(t, j);
      if (u.valid() && std::find(out.begin() + static_cast<std::ptrdiff_t>(begin), out.end(), u) == out.end())
        out.push_back(u);
    }
  }
}

std::vector<std::array<int, 2>> BackgroundMeshKernel<3>::edgePairs() const {
  std::vector<std::array<int, 2>> pairs;
  pairs.reserve(6 * mesh_->numTets());
  for (std::uint32_t k = 0; k < mesh_->tetSlots(); ++k) {
    if (!mesh_->isAlive(TetId(k))) continue;
    const std::uint32_t* tv = mesh_->tetVertices(TetId(k));
    for (const auto& e : kEdges) pairs.push_back({static_cast<int>(tv[e[0]]), static_cast<int>(tv[e[1]])});
  }
  return pairs;
}

Vec3 BackgroundMeshKernel<3>::centroid(TetId t) const {
  const std::uint32_t* tv = mesh_->tetVertices(t);
  Vec3 c = Vec3::Zero();
  for (int i = 0; i < 4; ++i) c += mesh_->point(VertexId(tv[i]));
  return c / 4;
}

bool BackgroundMeshKernel<3>::closureContains(TetId t, const Vec3& x) const {
  const std::uint32_t* tv = mesh_->tetVertices(t);
  for (int i = 0; i < 4; ++i) {
    const double* c[4] = {mesh_->coords(VertexId(tv[0])), mesh_->coords(VertexId(tv[1])),
                          mesh_->coords(VertexId(tv[2])), mesh_->coords(VertexId(tv[3]))};
    c[i] = x.data();
    if (predicates::orient3d(c[0], c[1], c[2], c[3]) < 0) return false;
  }
  return true;
}

Vec3 BackgroundMeshKernel<3>::circumcentre(TetId t) const {
  const std::uint32_t* tv = mesh_->tetVertices(t);
  const Vec3 a = mesh_->point(VertexId(tv[0])), b = mesh_->point(VertexId(tv[1])),
             c = mesh_->point(VertexId(tv[2])), d = mesh_->point(VertexId(tv[3]));
  const Vec3 ba = b - a, ca = c - a, da = d - a;
  const Vec3 n = ba.squaredNorm() * ca.cross(da) + ca.squaredNorm() * da.cross(ba) + da.squaredNorm() * ba.cross(ca);
  return a + n / (2 * ba.dot(ca.cross(da)));
}

bool BackgroundMeshKernel<3>::inSphere(TetId t, const Vec3& p) const {
  const std::uint32_t* tv = mesh_->tetVertices(t);
  return predicates::insphere(mesh_->coords(VertexId(tv[0])), mesh_->coords(VertexId(tv[1])),
                              mesh_->coords(VertexId(tv[2])), mesh_->coords(VertexId(tv[3])), p.data()) > 0;
}

double BackgroundMeshKernel<3>::maxEdgeLength(TetId t, const Mat3& m) const {
  const std::uint32_t* tv = mesh_->tetVertices(t);
  double len = 0;
  for (const auto& e : kEdges)
    len = std::max(len, (m * (mesh_->point(VertexId(tv[e[1]])) - mesh_->point(VertexId(tv[e[0]])))).norm());
  return len;
}

std::vector<std::string> BackgroundMeshKernel<3>::validate() const {
  del3d::ValidateOptions vo;
  vo.checkDelaunay = true;
  return del3d::validate(*mesh_, vo);
}

}  // namespace aniso
