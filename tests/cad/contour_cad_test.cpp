// Contour discretization and face boundaries on every public model (/work/shared/models):
// with a simple control space per face (isotropic h = 0.05 × model diagonal, M_p of the
// face's surface), every edge is discretized and every face boundary built, then checked:
//  - each boundary node's (u, v) maps onto its global node in 3D (within the CAD
//    tolerances), and no boundary step spans most of a period (loops chained across
//    seams; pole pieces, on one node, excepted);
//  - the face is on the left: outer loop of positive signed area, holes negative and
//    inside the outer loop (for faces whose loops are simple in (u, v));
//  - on every closed shell, each boundary segment (two different global nodes) is used by
//    exactly two face sides, once in each direction of the shell's orientation: the
//    boundary "mesh" of segments is closed and consistently oriented.
// A model that fails names itself and the face.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <sstream>

#include "cad/CadModel.h"
#include "mesher/core/Error.h"
#include "mesher/predicates/Predicates.h"
#include "mesher/surface/ContourDiscretization.h"

using namespace aniso;

namespace {

/// M_s = I / h, M_p from the surface (the g_min guard relative to the model).
class SimpleSpace final : public ControlSpace2d {
 public:
  SimpleSpace(SurfacePtr surface, const Box2& bounds, double h, double gMin)
      : surface_(std::move(surface)), bounds_(bounds), sizing_(Metric2d::isotropic(h)), gMin_(gMin) {}
  SurfaceMetricAt getMetric(const Vec2& uv) const override {
    const Vec2 p = bounds_.empty() ? uv : Vec2(uv.cwiseMax(bounds_.lo).cwiseMin(bounds_.hi));
    return {sizing_, surface_->parameterizationTensor(p, gMin_)};
  }
  Box2 bounds() const override { return bounds_; }

 private:
  SurfacePtr surface_;
  Box2 bounds_;
  Metric2d sizing_;
  double gMin_;
};

std::vector<std::string> modelFiles() {
  std::vector<std::string> out;
  const std::filesystem::path dir = std::filesystem::path(ANISOMESH_SHARED_DIR) / "models";
  if (!std::filesystem::is_directory(dir)) return out;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    std::string ext = entry.path().extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext == ".step" || ext == ".stp" || ext == ".brep" || ext == ".igs") out.push_back(entry.path().filename().string());
  }
  std::sort(out.begin(), out.end());
  return out;
}

double signedArea(const std::vector<BoundaryNode>& loop) {
  double a = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec2& p = loop[i].uv;
    const Vec2& q = loop[(i + 1) % loop.size()].uv;
    a += (p.x() - loop[0].uv.x()) * (q.y() - loop[0].uv.y()) - (q.x() - loop[0].uv.x()) * (p.y() - loop[0].uv.y());
  }
  return 0.5 * a;
}

/// True when no two non-adjacent boundary segments of the face cross properly in (u, v).
bool loopsAreSimple(const FaceBoundary& b) {
  struct Seg {
    Vec2 a, b;
    Box2 box;
  };
  std::vector<Seg> segs;
  for (const auto& loop : b.loops)
    for (std::size_t i = 0; i < loop.size(); ++i) {
      Seg s{loop[i].uv, loop[(i + 1) % loop.size()].uv, {}};
      s.box.add(s.a);
      s.box.add(s.b);
      segs.push_back(s);
    }
  using predicates::orient2d;
  for (std::size_t i = 0; i < segs.size(); ++i)
    for (std::size_t j = i + 1; j < segs.size(); ++j) {
      const Seg &s = segs[i], &t = segs[j];
      if (s.box.hi.x() < t.box.lo.x() || t.box.hi.x() < s.box.lo.x() || s.box.hi.y() < t.box.lo.y() ||
          t.box.hi.y() < s.box.lo.y())
        continue;
      const double o1 = orient2d(s.a.data(), s.b.data(), t.a.data()), o2 = orient2d(s.a.data(), s.b.data(), t.b.data());
      const double o3 = orient2d(t.a.data(), t.b.data(), s.a.data()), o4 = orient2d(t.a.data(), t.b.data(), s.b.data());
      if (o1 * o2 < 0 && o3 * o4 < 0) return false;
    }
  return true;
}

std::string describe(const Model& m, const SurfaceMesh& mesh, const BoundaryNode& n) {
  std::ostringstream s;
  const NodeOn& on = mesh.nodeOn[n.node];
  const char* kind = on.kind == NodeOn::Kind::Vertex ? "vertex" : on.kind == NodeOn::Kind::Edge ? "edge" : "face";
  s << "node " << n.node << " (" << kind << " " << on.entity + 1;
  if (on.kind == NodeOn::Kind::Edge) s << (m.edges[on.entity].degenerate ? " degenerate" : "") << " t=" << on.t;
  s << ") at (" << n.uv.x() << ", " << n.uv.y() << ")";
  return s.str();
}

/// How far surface(uv) of a boundary node may be from the node: the CAD tolerances, and 1%
/// of the mesh size for pcurves that are not parameterized like their 3D curve (e.g. in
/// submarine.stp a pcurve is 0.1 off its edge at the same t, 7e-4 being the edge's tolerance).
/// Crossing-number test of p against a closed polygon.
bool inside(const Vec2& p, const std::vector<BoundaryNode>& poly) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2 &a = poly[i].uv, &b = poly[j].uv;
    if ((a.y() > p.y()) != (b.y() > p.y()) && p.x() < (b.x() - a.x()) * (p.y() - a.y()) / (b.y() - a.y()) + a.x())
      in = !in;
  }
  return in;
}

/// Hole nodes outside the outer loop (nodes shared with the outer loop, where a hole
/// touches it, do not count).
int holeNodesOutside(const FaceBoundary& b) {
  int out = 0;
  for (std::size_t l = 1; l < b.loops.size(); ++l)
    for (const BoundaryNode& n : b.loops[l]) {
      bool onOuter = false;
      for (const BoundaryNode& o : b.loops[0]) onOuter = onOuter || (o.node == n.node && (o.uv - n.uv).norm() < 1e-9);
      if (!onOuter && !inside(n.uv, b.loops[0])) ++out;
    }
  return out;
}

double nodeTolerance(const Model& m, const ModelFace& f, const NodeOn& on, double h) {
  double t = f.tolerance;
  if (on.kind == NodeOn::Kind::Vertex) t = std::max(t, m.vertices[on.entity].tolerance);
  if (on.kind == NodeOn::Kind::Edge) t = std::max(t, m.edges[on.entity].tolerance);
  return 2 * t + 0.01 * h;
}

struct Summary {
  int nodes = 0, simpleFaces = 0, closedShells = 0;
  std::vector<int> nonSimple;  ///< 1-based faces whose loops cross in (u, v)
  double seconds = 0;
};

/// Nodes map onto the surface, steps do not jump periods, the face is on the left.
void checkFace(const Model& m, int f, const FaceBoundary& b, const SurfaceMesh& mesh, double h,
               const std::string& where, Summary& sum) {
  const ModelFace& face = m.faces[f];
  EXPECT_EQ(b.loops.size(), face.loops.size()) << where;
  const SurfaceDomain dom = face.surface->domain();
  const Vec2 period(dom.uPeriodic ? dom.uPeriod : 0, dom.vPeriodic ? dom.vPeriod : 0);
  for (std::size_t l = 0; l < b.loops.size(); ++l) {
    const auto& loop = b.loops[l];
    ASSERT_GE(loop.size(), 3u) << where << " loop " << l + 1;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const BoundaryNode& n = loop[i];
      const double d = (face.surface->point(n.uv) - mesh.nodes[n.node]).norm();
      ASSERT_LE(d, nodeTolerance(m, face, mesh.nodeOn[n.node], h))
          << where << " loop " << l + 1 << " " << describe(m, mesh, n);
      const BoundaryNode& next = loop[(i + 1) % loop.size()];
      const Vec2 step = (next.uv - n.uv).cwiseAbs();
      for (int k = 0; k < 2; ++k)
        if (period[k] > 0 && n.node != next.node) {
          ASSERT_LT(step[k], 0.75 * period[k]) << where << " loop " << l + 1 << " step " << i << " from "
                                               << describe(m, mesh, n) << " to " << describe(m, mesh, next);
        }
    }
  }
  if (!loopsAreSimple(b)) {
    sum.nonSimple.push_back(f + 1);
    return;
  }
  ++sum.simpleFaces;
  for (std::size_t l = 0; l < b.loops.size(); ++l)
    EXPECT_EQ(signedArea(b.loops[l]) > 0, l == 0) << where << " loop " << l + 1 << " has area " << signedArea(b.loops[l]);
  EXPECT_EQ(holeNodesOutside(b), 0) << where << ": holes outside the outer loop in (u,v)";
}

/// Closed shells: every segment used twice, once each way.
void checkShells(const Model& m, const std::vector<FaceBoundary>& boundaries, const SurfaceMesh& mesh,
                 const std::string& name, Summary& sum) {
  for (std::size_t s = 0; s < m.shells.size(); ++s) {
    const ModelShell& shell = m.shells[s];
    if (!shell.closed) continue;
    ++sum.closedShells;
    std::map<std::pair<int, int>, std::pair<int, int>> uses;  // (lo, hi) → (count, net direction)
    for (const FaceUse& fu : shell.faces)
      for (const auto& loop : boundaries[fu.face].loops)
        for (std::size_t i = 0; i < loop.size(); ++i) {
          int a = loop[i].node, c = loop[(i + 1) % loop.size()].node;
          if (a == c) continue;
          // The loops have the face on the left seen from pu × pv; the shell's side is the
          // other one when the face is reversed in it.
          if (fu.reversed) std::swap(a, c);
          auto& u = uses[{std::min(a, c), std::max(a, c)}];
          ++u.first;
          u.second += a < c ? 1 : -1;
        }
    int bad = 0;
    std::ostringstream first;
    for (const auto& [seg, u] : uses)
      if (u.first != 2 || u.second != 0) {
        if (bad++ == 0)
          first << "segment (" << seg.first << ", " << seg.second << ") used " << u.first << " times, net direction "
                << u.second << " (first node on " << static_cast<int>(mesh.nodeOn[seg.first].kind) << " "
                << mesh.nodeOn[seg.first].entity + 1 << ")";
      }
    EXPECT_EQ(bad, 0) << name << " shell " << s + 1 << ": " << bad << " bad segments, first " << first.str();
  }
}

/// Discretizes all edges with h = hRel × diagonal and checks every face and closed shell.
Summary checkModel(const Model& m, const std::string& name, double hRel) {
  Summary sum;
  const auto start = std::chrono::steady_clock::now();
  const double diag = m.diagonal();
  const double h = hRel * diag, gMin = (1e-4 * diag) * (1e-4 * diag);
  std::vector<std::unique_ptr<SimpleSpace>> spaces;
  std::vector<const ControlSpace2d*> ptrs;
  for (const ModelFace& f : m.faces) {
    spaces.push_back(std::make_unique<SimpleSpace>(f.surface, f.uvBounds, h, gMin));
    ptrs.push_back(spaces.back().get());
  }
  SurfaceMesh mesh;
  std::vector<EdgeDiscretization> edges;
  try {
    edges = discretizeEdges(m, ptrs, {}, mesh);
  } catch (const MeshingError& e) {
    ADD_FAILURE() << name << ": " << e.what();
    return sum;
  }
  sum.nodes = static_cast<int>(mesh.nodes.size());
  std::vector<FaceBoundary> boundaries(m.faces.size());
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    try {
      boundaries[f] = faceBoundary(m, static_cast<int>(f), edges, mesh);
    } catch (const MeshingError& e) {
      ADD_FAILURE() << name << ": " << e.what();
      continue;
    }
    checkFace(m, static_cast<int>(f), boundaries[f], mesh, h, name + " face " + std::to_string(f + 1), sum);
  }
  checkShells(m, boundaries, mesh, name, sum);
  sum.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return sum;
}

class ContourCad : public ::testing::TestWithParam<std::string> {};

TEST_P(ContourCad, BoundariesClosedOrientedAndShared) {
  const std::string name = GetParam();
  const auto start = std::chrono::steady_clock::now();
  cad::CadModel cm = cad::CadModel::read(std::string(ANISOMESH_SHARED_DIR) + "/models/" + name);
  cm.prepare({});
  const Model m = cm.topology();
  ASSERT_GT(m.diagonal(), 0) << name;
  const double readSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << "  " << name << ": " << m.faces.size() << " faces, read in " << readSeconds << " s\n";
  for (double hRel : {0.05, 0.005}) {
    SCOPED_TRACE("h = " + std::to_string(hRel) + " x diagonal");
    const Summary s = checkModel(m, name, hRel);
    std::cout << "    h/diag " << hRel << ": " << s.nodes << " boundary nodes, " << s.simpleFaces
              << " faces with simple loops, " << s.closedShells << " closed shells, " << s.seconds << " s";
    if (!s.nonSimple.empty()) {
      std::cout << "; loops cross in (u,v) on faces";
      for (int f : s.nonSimple) std::cout << " " << f;
    }
    std::cout << "\n";
  }
}

std::string testName(const ::testing::TestParamInfo<std::string>& info) {
  std::string s = info.param;
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s;
}

INSTANTIATE_TEST_SUITE_P(PublicModels, ContourCad, ::testing::ValuesIn(modelFiles()), testName);

TEST(ContourCadModels, Present) { EXPECT_GE(modelFiles().size(), 30u) << "the public models are missing"; }

}  // namespace
