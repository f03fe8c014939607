// Tests of the proximity check of alg. 3.3 (mesher/volume/ThinBoundary.h) on hand-made
// solids: a slab thinner than its surface triangles, and a cube that is not.
#include <gtest/gtest.h>

#include <map>

#include "mesher/volume/ThinBoundary.h"
#include "volume_refine_fixture.h"

using namespace aniso;
using namespace aniso::testing;

namespace {

/// The unit square times `thickness` (cubeSolid mapped, Delaunay in space as the volume
/// mesher's isotropic triangulation of the boundary nodes), n×n points per face.
SolidTetMesh slab(int n, double thickness, std::set<Triple>& boundary) {
  Mat3 map = Mat3::Identity();
  map(2, 2) = thickness;
  return cubeSolid(n, boundary, 7, map, false);
}

/// The boundary triangles turned outward (the slab is convex: away from its centre).
std::vector<std::array<int, 3>> outward(const SurfaceMesh& surface) {
  Vec3 centre = Vec3::Zero();
  for (const Vec3& p : surface.nodes) centre += p;
  centre /= static_cast<double>(surface.nodes.size());
  std::vector<std::array<int, 3>> out = surface.triangles;
  for (auto& t : out) {
    const Vec3 a = surface.nodes[t[0]], b = surface.nodes[t[1]], c = surface.nodes[t[2]];
    if ((b - a).cross(c - a).dot(a - centre) < 0) std::swap(t[1], t[2]);
  }
  return out;
}

/// The triangles (surface node triples) and their faces as a SolidBoundary in s's kernel
/// ids; a triangle with a node s lacks is left out.
SolidBoundary kernelBoundary(const SolidTetMesh& s, const std::vector<std::array<int, 3>>& triangles,
                             const std::vector<int>& faces) {
  std::map<int, del3d::VertexId> vertexOf;
  for (std::uint32_t v = 0; v < s.node.size(); ++v)
    if (s.node[v] >= 0) vertexOf.emplace(s.node[v], del3d::VertexId(v));
  SolidBoundary b;
  for (std::size_t k = 0; k < triangles.size(); ++k) {
    std::array<del3d::VertexId, 3> t;
    bool all = true;
    for (int j = 0; j < 3; ++j) {
      const auto it = vertexOf.find(triangles[k][j]);
      all = all && it != vertexOf.end();
      if (all) t[j] = it->second;
    }
    if (!all) continue;
    b.triangles.push_back(t);
    b.triangleFace.push_back(faces[k]);
  }
  b.embeddedFrom = b.triangles.size();
  return b;
}

std::vector<ThinSpot> thinSpots(const SolidTetMesh& s, const std::set<Triple>& boundary) {
  const CubeSurface c = cubeSurface(s, boundary);
  return findThinBoundary(s, kernelBoundary(s, outward(c.surface), c.surface.triangleFace));
}

TEST(ThinBoundary, ASlabThinnerThanItsTrianglesIsFound) {
  std::set<Triple> boundary;
  const SolidTetMesh s = slab(8, 0.04, boundary);  // triangles ~0.14 across, 0.04 thick
  const std::vector<ThinSpot> spots = thinSpots(s, boundary);
  ASSERT_FALSE(spots.empty());
  std::set<int> faces;
  for (const ThinSpot& t : spots) {
    faces.insert(t.face);
    EXPECT_LE(t.thickness, 0.04 + 1e-12);
    EXPECT_GT(t.thickness, 0.0);
    EXPECT_LT(t.thickness, kThinRatio * t.size);
  }
  EXPECT_EQ(faces, (std::set<int>{4, 5}));  // the two big faces (normal along z), nothing on the rims
  const std::vector<SizingSource> sources = thinSources(spots, 1e-3);
  ASSERT_EQ(sources.size(), 2u);
  for (const SizingSource& src : sources) {
    EXPECT_EQ(src.kind, SizingSource::Kind::Box);
    EXPECT_NEAR(src.metric.axes().lengths.maxCoeff(), 0.04, 0.04 * 0.5);
    EXPECT_TRUE(src.contains(Vec3(0.5, 0.5, 0.02)));
  }
}

TEST(ThinBoundary, HminBoundsTheSourcesAndStopsTheLoop) {
  std::set<Triple> boundary;
  const SolidTetMesh s = slab(8, 0.04, boundary);
  const std::vector<ThinSpot> spots = thinSpots(s, boundary);
  // hmin 0.06: sources at 0.06 (the triangles are larger than 0.06 / kThinRatio)
  for (const SizingSource& src : thinSources(spots, 0.06)) EXPECT_NEAR(src.metric.axes().lengths.minCoeff(), 0.06, 1e-12);
  // hmin as large as the triangles: nothing left to refine
  EXPECT_TRUE(thinSources(spots, 1.0).empty());
}

TEST(ThinBoundary, SourcesScaledToTheBudget) {
  std::set<Triple> boundary;
  const SolidTetMesh s = slab(8, 0.04, boundary);
  const CubeSurface c = cubeSurface(s, boundary);
  const std::vector<SizingSource> sources = thinSources(thinSpots(s, boundary), 1e-3);
  const double n = static_cast<double>(c.surface.triangles.size());
  const double asked = predictedTriangles(c.surface, sources);
  ASSERT_GT(asked, 3 * n);  // the slab's faces ask for a lot more triangles
  // Within the budget: the sources as they are.
  double factor = 0;
  const std::vector<SizingSource> same = sourcesWithinBudget(c.surface, sources, asked * 1.01, &factor);
  EXPECT_EQ(factor, 1.0);
  ASSERT_EQ(same.size(), sources.size());
  for (std::size_t i = 0; i < same.size(); ++i)
    EXPECT_EQ(same[i].metric.axes().lengths.minCoeff(), sources[i].metric.axes().lengths.minCoeff());
  // Over it: every size scaled by one factor > 1, the prediction within the budget and close
  // to it (the factor is the smallest to 1 %).
  const double budget = 0.5 * (asked + n);
  const std::vector<SizingSource> scaled = sourcesWithinBudget(c.surface, sources, budget, &factor);
  EXPECT_GT(factor, 1.0);
  ASSERT_EQ(scaled.size(), sources.size());
  for (std::size_t i = 0; i < scaled.size(); ++i) {
    EXPECT_NEAR(scaled[i].metric.axes().lengths.minCoeff(), factor * sources[i].metric.axes().lengths.minCoeff(), 1e-12);
    EXPECT_TRUE(scaled[i].contains(Vec3(0.5, 0.5, 0.02)));
  }
  const double predicted = predictedTriangles(c.surface, scaled);
  EXPECT_LE(predicted, budget);
  std::vector<SizingSource> finer = sources;  // 2 % below the factor: over the budget
  for (SizingSource& src : finer) src.metric = Metric3d::isotropic(factor / 1.02 * src.metric.axes().lengths.minCoeff());
  EXPECT_GT(predictedTriangles(c.surface, finer), budget);
  EXPECT_GT(predicted, n);  // still refines
}

TEST(ThinBoundary, FoundBeforeCarvingAndWithTrianglesMissing) {
  // the slab's boundary nodes triangulated with the enclosing box kept (as before carving):
  // the tet on each boundary triangle's inner side is the one that counts
  std::set<Triple> boundary;
  const SolidTetMesh carved = slab(8, 0.04, boundary);
  const std::vector<ThinSpot> after = thinSpots(carved, boundary);
  ASSERT_FALSE(after.empty());
  Mat3 map = Mat3::Identity();
  map(2, 2) = 0.04;
  std::set<Triple> none;
  const SolidTetMesh s = cubeSolid(8, none, 7, map, false, false);
  const int nodes = static_cast<int>(cubeSurfacePoints(8, 7).size());
  const CubeSurface c = cubeSurface(carved, boundary);
  std::vector<std::array<int, 3>> triangles = outward(c.surface);
  const std::vector<ThinSpot> before = findThinBoundary(s, kernelBoundary(s, triangles, c.surface.triangleFace));
  EXPECT_GE(before.size(), after.size() * 9 / 10);
  for (const ThinSpot& t : before) EXPECT_LE(t.thickness, 0.04 + 1e-12);
  // a triangle absent from the mesh (here: made of nodes no tet has together) is skipped
  std::vector<int> faces = c.surface.triangleFace;
  triangles.push_back({0, nodes / 2, nodes - 1});
  faces.push_back(0);
  const std::vector<ThinSpot> missing = findThinBoundary(s, kernelBoundary(s, triangles, faces));
  EXPECT_EQ(missing.size(), before.size());
}

TEST(ThinBoundary, ACubeIsNotThin) {
  std::set<Triple> boundary;
  const SolidTetMesh s = cubeSolid(8, boundary);
  EXPECT_TRUE(thinSpots(s, boundary).empty());
}

}  // namespace

TEST(ThinBoundary, SourcesSizeOnlyTheFacesOfTheThinSolid) {
  std::set<Triple> boundary;
  const SolidTetMesh s = slab(8, 0.04, boundary);
  CubeSurface c = cubeSurface(s, boundary);
  std::vector<ThinSpot> spots = thinSpots(s, boundary);
  for (ThinSpot& t : spots) t.solid = 0;
  // solid 0: the slab's faces 0..5; solid 1: faces 6 and 7, a part lying in the slab's box
  Model model;
  model.faces.resize(8);
  model.shells.push_back({});
  for (int f = 0; f < 6; ++f) model.shells[0].faces.push_back({f, false});
  model.shells.push_back({{{6, false}, {7, false}}, true});
  model.solids.push_back({"slab", 0, {}, {}, 0});
  model.solids.push_back({"part", 1, {}, {}, 0});
  const std::vector<SizingSource> sources = thinSources(spots, 1e-3, nullptr, &model);
  ASSERT_EQ(sources.size(), 2u);
  for (const SizingSource& src : sources) {
    EXPECT_EQ(src.faces, (std::vector<int>{0, 1, 2, 3, 4, 5}));
    EXPECT_TRUE(src.sizesFace(4));
    EXPECT_FALSE(src.sizesFace(6));
  }
  EXPECT_TRUE(thinSources(spots, 1e-3).front().faces.empty());  // without the model: every face
  // the same triangles given to the other part count once each: nothing asks them finer
  const double asked = predictedTriangles(c.surface, sources);
  int moved = 0;
  for (std::size_t t = 0; t < c.surface.triangles.size(); ++t)
    if (c.surface.triangleFace[t] == 4) c.surface.triangleFace[t] = 6, ++moved;
  ASSERT_GT(moved, 0);
  const double after = predictedTriangles(c.surface, sources);
  EXPECT_LT(after, asked);
  EXPECT_GE(after, static_cast<double>(c.surface.triangles.size()));
  // and none of them gets into the user-sizing sum of a point (face sources are not regions)
  UserSizing user;
  user.sources = sources;
  EXPECT_FALSE(user.metricAt(Vec3(0.5, 0.5, 0.02)).has_value());
}

TEST(ThinBoundary, AFewThinnerSpotsDoNotSizeTheWholeFace) {
  std::set<Triple> boundary;
  const SolidTetMesh s = slab(8, 0.04, boundary);
  std::vector<ThinSpot> spots = thinSpots(s, boundary);
  ASSERT_GT(spots.size(), 40u);
  // fewer than kFaceThicknessQuantile of the spots measured 20x thinner (an apex near a
  // coarse triangle's chord plane): the face still asks for the slab's thickness
  std::size_t outliers = 0;
  for (std::size_t i = 0; i < spots.size(); i += 25, ++outliers) spots[i].thickness = 0.002;
  ASSERT_LT(static_cast<double>(outliers), 0.5 * kFaceThicknessQuantile * spots.size());
  for (const SizingSource& src : thinSources(spots, 1e-4))
    EXPECT_NEAR(src.metric.axes().lengths.minCoeff(), 0.04, 0.04 * 0.5);
  // every spot that thin: the face asks for it
  for (ThinSpot& t : spots) t.thickness = 0.002;
  for (const SizingSource& src : thinSources(spots, 1e-4)) EXPECT_NEAR(src.metric.axes().lengths.minCoeff(), 0.002, 1e-12);
}

TEST(ThinBoundary, ScalingStopsAtTheLargestFactor) {
  std::set<Triple> boundary;
  const SolidTetMesh s = slab(8, 0.04, boundary);
  const CubeSurface c = cubeSurface(s, boundary);
  const std::vector<SizingSource> sources = thinSources(thinSpots(s, boundary), 1e-3);
  const double n = static_cast<double>(c.surface.triangles.size());
  double factor = 0;
  // a budget no scaling up to 1.5 meets: scaled by 1.5, the prediction still over it
  const std::vector<SizingSource> capped = sourcesWithinBudget(c.surface, sources, 1.01 * n, &factor, 1.5);
  EXPECT_EQ(factor, 1.5);
  ASSERT_EQ(capped.size(), sources.size());
  EXPECT_NEAR(capped[0].metric.axes().lengths.minCoeff(), 1.5 * sources[0].metric.axes().lengths.minCoeff(), 1e-12);
  EXPECT_GT(predictedTriangles(c.surface, capped), 1.01 * n);
}

TEST(ThinBoundary, TheThinSolidsThatFitTheBudgetAreKept) {
  std::set<Triple> boundary;
  const SolidTetMesh s = slab(8, 0.04, boundary);
  const CubeSurface c = cubeSurface(s, boundary);
  // two "solids": the slab's top face sized at 0.04 (cheap), its bottom face at 0.01 (16x
  // the triangles); each source sizes its own face only
  std::vector<SizingSource> sources = thinSources(thinSpots(s, boundary), 1e-3);
  ASSERT_EQ(sources.size(), 2u);
  sources[0].faces = {4};
  sources[1].faces = {5};
  sources[0].metric = Metric3d::isotropic(0.01);
  sources[1].metric = Metric3d::isotropic(0.04);
  const double n = static_cast<double>(c.surface.triangles.size());
  const double cheap = predictedTriangles(c.surface, {sources[1]}) - n;
  const double dear = predictedTriangles(c.surface, {sources[0]}) - n;
  ASSERT_GT(dear, 4 * cheap);
  std::size_t groups = 0, kept = 0;
  // room for the cheap one only: it is kept, whatever its place in the list
  EXPECT_EQ(cheapestGroupsWithinBudget(c.surface, sources, n + cheap + 0.5 * dear, &groups, &kept),
            (std::vector<std::size_t>{1}));
  EXPECT_EQ(groups, 2u);
  EXPECT_EQ(kept, 1u);
  // room for both: both, in the list's order
  EXPECT_EQ(cheapestGroupsWithinBudget(c.surface, sources, n + cheap + dear + 1), (std::vector<std::size_t>{0, 1}));
  // room for neither
  EXPECT_TRUE(cheapestGroupsWithinBudget(c.surface, sources, n + 0.5 * cheap, &groups, &kept).empty());
  EXPECT_EQ(kept, 0u);
}

// The prediction against its definition (every triangle's target the smallest size of the
// sources containing its centroid, restricted to their faces): many small sources (a grid
// cell query each) and large ones (their faces' triangles), balls, capsules and boxes.
TEST(ThinBoundary, PredictedTrianglesAsDefined) {
  std::set<Triple> boundary;
  const SolidTetMesh s = slab(12, 0.05, boundary);
  const CubeSurface c = cubeSurface(s, boundary);
  const SurfaceMesh& m = c.surface;
  std::vector<SizingSource> sources;
  std::uint64_t x = 99;
  auto next = [&x] { return (x = x * 6364136223846793005ull + 1442695040888963407ull) >> 11; };
  auto unit = [&] { return static_cast<double>(next() % 1000001) / 1e6; };
  for (int k = 0; k < 300; ++k) {
    SizingSource src;
    src.kind = static_cast<SizingSource::Kind>(k % 3);
    src.a = Vec3(unit(), unit(), 0.05 * unit());
    src.b = src.a + Vec3(0.2 * unit(), 0.2 * unit(), 0.02);
    src.radius = k % 10 == 0 ? 0.8 : 0.05 * unit();  // a few cover most of the slab
    src.metric = Metric3d::isotropic(0.002 + 0.05 * unit());
    if (k % 2 == 0) src.faces = {static_cast<int>(next() % 6)};
    if (k % 6 == 0) src.faces = {};
    sources.push_back(src);
  }
  double expected = 0;
  for (std::size_t i = 0; i < m.triangles.size(); ++i) {
    const auto& t = m.triangles[i];
    const Vec3 p[3] = {m.nodes[t[0]], m.nodes[t[1]], m.nodes[t[2]]};
    const Vec3 centroid = (p[0] + p[1] + p[2]) / 3;
    double target = 1e300;
    for (const SizingSource& src : sources)
      if (src.sizesFace(m.triangleFace[i]) && src.contains(centroid))
        target = std::min(target, src.metric.axes().lengths.minCoeff());
    const double size = ((p[1] - p[0]).norm() + (p[2] - p[1]).norm() + (p[0] - p[2]).norm()) / 3;
    expected += std::max(1.0, (size / target) * (size / target));
  }
  EXPECT_GT(expected, 2.0 * static_cast<double>(m.triangles.size()));  // the sources refine
  EXPECT_EQ(predictedTriangles(m, sources), expected);
}
