#include "mesher/pipeline/SurfaceMesher.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>

#include "mesher/core/Cancel.h"
#include "mesher/core/Error.h"
#include "mesher/core/Log.h"
#include "mesher/core/ParallelFor.h"
#include "mesher/core/PredictionBoard.h"
#include "mesher/sizing/BoundaryUpdate.h"
#include "mesher/sizing/FaceControlSpace.h"
#include "mesher/sizing/VolumeChordBound.h"
#include "mesher/sizing/SurfaceBudget.h"
#include "mesher/quad/QuadSizing.h"
#include "mesher/surface/ContourDiscretization.h"
#include "mesher/surface/contour/CoincidentFaces.h"
#include "mesher/surface/improve/FaceQuality.h"
#include "mesher/model/EdgeNormals.h"

namespace aniso {
namespace {

using Clock = std::chrono::steady_clock;
double since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

bool faceMeshed(const SurfaceMesherInput& in, int f) {
  if (!in.skipFaces.empty() && in.skipFaces[static_cast<std::size_t>(f)]) return false;
  return !in.model->faces[static_cast<std::size_t>(f)].loops.empty();
}

/// Removes pairs of triangles of one face that have the same three nodes with opposite
/// orientations, from index `first` on. They arise where a face's parametric mesh folds
/// onto itself in 3D (at a pole next to a seam both sides of the seam can close the same
/// triangle); as a 2-chain such a pair sums to zero, so removing it leaves the mesh's
/// boundary unchanged. Returns the number of triangles removed.
int cancelFoldedPairs(SurfaceMesh& mesh, std::size_t first) {
  struct Key {
    std::array<int, 3> sorted;
    bool even;  ///< orientation class of the node order
    std::size_t index;
  };
  std::vector<Key> keys;
  // (a hash of the sorted nodes, position in keys): one sort of 16-byte pairs finds the
  // candidates; only triangles whose hash repeats are compared node by node
  std::vector<std::pair<std::uint64_t, std::uint32_t>> hashed;
  for (std::size_t t = first; t < mesh.triangles.size(); ++t) {
    std::array<int, 3> n = mesh.triangles[t];
    // Rotate so the smallest node is first; the parity of the rest gives the orientation.
    const int k = static_cast<int>(std::min_element(n.begin(), n.end()) - n.begin());
    std::rotate(n.begin(), n.begin() + k, n.end());
    const bool even = n[1] < n[2];
    std::array<int, 3> s = n;
    std::sort(s.begin(), s.end());
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (const int v : s) h = (h ^ static_cast<std::uint32_t>(v)) * 0xFF51AFD7ED558CCDull, h ^= h >> 32;
    hashed.push_back({h, static_cast<std::uint32_t>(keys.size())});
    keys.push_back({s, even, t});
  }
  std::sort(hashed.begin(), hashed.end());
  std::vector<std::uint8_t> drop(mesh.triangles.size(), 0);
  std::vector<Key> group;
  for (std::size_t i = 0; i < hashed.size();) {
    std::size_t j = i + 1;
    while (j < hashed.size() && hashed[j].first == hashed[i].first) ++j;
    if (j - i < 2) {
      i = j;
      continue;
    }
    group.clear();
    for (std::size_t k = i; k < j; ++k) group.push_back(keys[hashed[k].second]);
    std::sort(group.begin(), group.end(), [](const Key& a, const Key& b) {
      return a.sorted != b.sorted ? a.sorted < b.sorted : a.index < b.index;
    });
    for (std::size_t g = 0; g < group.size();) {
      std::size_t h = g;
      while (h < group.size() && group[h].sorted == group[g].sorted) ++h;
      // Pair up opposite orientations within the triangles of the same nodes.
      std::vector<std::size_t> pos, neg;
      for (std::size_t k = g; k < h; ++k) (group[k].even ? pos : neg).push_back(group[k].index);
      for (std::size_t k = 0; k < std::min(pos.size(), neg.size()); ++k) drop[pos[k]] = drop[neg[k]] = 1;
      g = h;
    }
    i = j;
  }
  std::size_t w = first;
  int removed = 0;
  for (std::size_t t = first; t < mesh.triangles.size(); ++t) {
    if (drop[t]) {
      ++removed;
      continue;
    }
    mesh.triangles[w] = mesh.triangles[t];
    mesh.triangleFace[w] = mesh.triangleFace[t];
    ++w;
  }
  mesh.triangles.resize(w);
  mesh.triangleFace.resize(w);
  return removed;
}

/// discretizeEdges; an edge that cannot be discretized takes its faces out of the run (their
/// control spaces set to null, the edge's error among their problems), then the others are
/// discretized again: at most once per face.
std::vector<EdgeDiscretization> discretizeEdgesLeavingOut(const Model& model, std::vector<const ControlSpace2d*>& cs,
                                                          const ContourOptions& copt, SurfaceMesh& trial,
                                                          std::vector<FaceOutcome>& outcomes) {
  for (std::size_t attempt = 0;; ++attempt) {
    try {
      trial = SurfaceMesh{};
      return discretizeEdges(model, cs, copt, trial);
    } catch (const EntityError& e) {
      if (e.kind() != EntityKind::Edge || attempt >= model.faces.size()) throw;
      bool removed = false;
      for (const int f : model.edges[static_cast<std::size_t>(e.index())].faces) {
        if (!cs[static_cast<std::size_t>(f)]) continue;
        cs[static_cast<std::size_t>(f)] = nullptr;
        outcomes[static_cast<std::size_t>(f)].problems.push_back(e.what());
        removed = true;
      }
      if (!removed) throw;
    }
  }
}

}  // namespace

bool SurfaceMeshResult::ok() const {
  return std::all_of(faces.begin(), faces.end(), [](const FaceOutcome& f) { return f.problems.empty(); });
}

SurfaceMeshResult meshSurfaces(const SurfaceMesherInput& in) {
  const Model& model = *in.model;
  const int nf = static_cast<int>(model.faces.size());
  SurfaceMeshResult r;
  r.faces.resize(nf);

  // 1: control spaces.
  auto t = Clock::now();
  std::vector<std::unique_ptr<CSQuadtree2d>> spaces(nf);
  const double chord = in.chordDeviation
                           ? *in.chordDeviation
                           : volumeChordDeviation(model, in.options.sizing.chordDeviationRel * model.diagonal());
  const CancelToken* cancel = in.options.cancel.get();
  parallelFor(nf, in.options.threads, [&](int f) {
    if (!faceMeshed(in, f)) return;
    checkCancel(cancel, "control spaces");
    FaceSizingInput fin;
    fin.model = &model;
    fin.face = f;
    fin.params = in.options.sizing;
    fin.analytic = in.analytic;
    fin.user = in.user;
    fin.chordDeviation = chord;
    try {
      spaces[f] = buildFaceControlSpace(fin);
    } catch (const Cancelled&) {
      throw;
    } catch (const MeshingError& e) {  // this face only: left out (no control space), the others go on
      std::string what = e.what();
      if (const std::string own = "face " + std::to_string(f + 1) + ": "; what.rfind(own, 0) == 0) what.erase(0, own.size());
      r.faces[f].problems.push_back(what);
    }
  }, "control spaces");
  r.times.emplace_back("control_space", since(t));

  // 2: edges, and the updates of alg. 3.1 from the discretized boundaries (segment
  // lengths, vicinity), repeated until no control space changes (at most kRounds times).
  t = Clock::now();
  std::vector<const ControlSpace2d*> cs(nf, nullptr);
  for (int f = 0; f < nf; ++f) cs[f] = spaces[f].get();
  // --quad: the triangles are made in a coarser view of each control space, so that merged
  // pairs are unit quads (mesher/quad/QuadSizing.h); conversion and quality use spaces[f].
  std::vector<std::unique_ptr<quad::QuadSizedSpace>> quadSized(nf);
  if (in.options.quad)
    for (int f = 0; f < nf; ++f)
      if (cs[f]) cs[f] = (quadSized[f] = std::make_unique<quad::QuadSizedSpace>(*cs[f])).get();
  ContourOptions copt;
  copt.evenSegments = in.options.quad;
  // The boundary sources respect h_min, or a thin face's own h_min (BoundaryUpdate.h):
  // without a floor, tiny CAD edges and sliver faces would drive the edge discretization
  // down to round-off (measured: boundary nodes 1e-7 apart, unrecoverable edges on part.step).
  const double hMin = in.options.sizing.hminFor(model.diagonal());
  // a volume mesh: no thin face gets its own h_min (BoundaryUpdate.h)
  const bool volume = in.options.dim == 3 || (in.options.dim == 0 && !model.solids.empty());
  constexpr int kRounds = 3;
  // then, while a face's boundary crosses itself in (u, v), rounds of the crossing rule only
  constexpr int kCrossingRounds = 4;
  std::vector<EdgeDiscretization> edges;
  std::vector<FaceBoundary> boundaries(nf);
  // a volume mesh's film rims (BoundaryUpdate.h: never steps)
  const std::vector<std::uint8_t> filmRim = volume ? filmRims(model) : std::vector<std::uint8_t>(static_cast<std::size_t>(nf), 0);
  const auto discretizeContours = [&] {
    for (int round = 0;; ++round) {  // bounded: updates stop after kRounds + kCrossingRounds
      checkCancel(cancel, "contours");
      SurfaceMesh trial;
      edges = discretizeEdgesLeavingOut(model, cs, copt, trial, r.faces);
      for (int f = 0; f < nf; ++f) {
        if (!cs[f]) continue;
        try {
          boundaries[f] = faceBoundary(model, f, edges, trial);
        } catch (const MeshingError& e) {  // this face only: left out, the others go on
          r.faces[f].problems.push_back(e.what());
          cs[f] = nullptr;
        }
      }
      std::atomic<int> updates{0};
      if (round < kRounds + kCrossingRounds) {
        parallelFor(nf, in.options.threads, [&](int f) {
          if (!cs[f]) return;
          checkCancel(cancel, "boundary sizing");
          BoundaryUpdateOptions bopt;
          bopt.hMin = hMin;
          bopt.cadTolerance = model.faces[f].tolerance;
          bopt.thinFaces = !volume;
          bopt.gapsAlongSegments = !volume;
          bopt.crossingsOnly = round >= kRounds;
          bopt.filmRim = filmRim[f] != 0;
          const BoundaryUpdateStats u = updateFromBoundary(*spaces[f], boundaries[f], in.options.sizing, bopt);
          if (u.total() == 0) return;
          logDebug("face " + std::to_string(f + 1) + " boundary sizing: " + std::to_string(u.shortSegments) +
                   " short segments, " + std::to_string(u.gaps) + " gaps (" + std::to_string(u.unresolvedGaps) +
                   " too narrow), " + std::to_string(u.crossings) + " crossing segments, " +
                   std::to_string(u.stepEnds) + " step ends, h_min " + std::to_string(u.faceMinSize));
          spaces[f]->smoothGradation(in.options.sizing.gradation);
          updates += u.total();
        }, "boundary sizing");
      }
      if (updates == 0) {
        r.mesh = std::move(trial);
        break;
      }
      logDebug("boundary sizing round " + std::to_string(round + 1) + ": " + std::to_string(updates.load()) +
               " sources");
    }
  };
  discretizeContours();
  for (int f = 0; f < nf; ++f)
    if (!cs[f]) {  // faces left out: no space, no prediction
      quadSized[f].reset();
      spaces[f].reset();
    }
  r.times.emplace_back("contours", since(t));

  // 2b: the element budget (thesis 6.5, mesher/sizing/SurfaceBudget.h): over it, every size
  // below a floor is raised to it and the contours are discretized again; when even h_max
  // cannot fit, the run stops before meshing (InputError).
  t = Clock::now();
  r.budget = surfaceBudget(model, spaces, boundaries, in.options);
  if (!r.budget.fits) throw InputError(budgetRefusal(r.budget));
  if (applyBudgetFloor(r.budget, spaces)) {
    discretizeContours();
    MeshOptions predictOnly = in.options;
    predictOnly.maxElements = 0;
    r.budget.predictedAfter = surfaceBudget(model, spaces, boundaries, predictOnly).predicted;
  }
  r.times.emplace_back("budget", since(t));

  // 3: faces.
  t = Clock::now();
  std::vector<FaceMeshResult> meshes(nf);
  PredictionBoard predicted(nf);
  PhaseProgress faceProgress("faces", nf, [&predicted] {
    std::string text = std::to_string(static_cast<long long>(predicted.total()));
    text.append(" triangles predicted");
    return text;
  });
  parallelFor(nf, in.options.threads, [&](int f) {
    if (!cs[f]) return;
    checkCancel(cancel, "surface mesh");
    FaceMesherOptions fo = in.face;
    fo.cancel = cancel;
    fo.surface = model.faces[f].surface.get();
    fo.onPrediction = [&predicted, &faceProgress, f](double n) {
      predicted.post(f, n);
      faceProgress.tick();
    };
    meshes[f] = meshFace(boundaries[f], *cs[f], fo);
    predicted.post(f, static_cast<double>(meshes[f].mesh.triangles.size()));
    FaceOutcome& o = r.faces[f];
    o.stats = meshes[f].stats;
    o.problems = meshes[f].problems;
    if (meshes[f].ok()) {
      FaceMesh& fm = meshes[f].mesh;
      if (in.options.quad) {
        quad::QuadOptions qo;
        qo.merge.method = in.options.quadMethod;
        qo.cancel = cancel;
        o.quad = quad::convertToQuads(fm, *spaces[f], model.faces[f].surface.get(), r.mesh.nodes, qo);
      }
      const FaceQuality q = faceQuality(fm.uv, fm.triangles, *spaces[f]);
      o.quality = {q.eta, in.options.quad ? o.quad.mu : q.mu, q.ek};
    }
  }, faceProgress);
  r.times.emplace_back("faces", since(t));

  // 4: assembly, in face order.
  t = Clock::now();
  // faces that coincide with an earlier one take its triangles (contour/CoincidentFaces.h)
  std::vector<int> twin(nf, -1);
  if (!in.options.quad) {
    std::vector<const FaceMesh*> meshed(nf, nullptr);
    for (int f = 0; f < nf; ++f)
      if (cs[f] && meshes[f].ok()) meshed[f] = &meshes[f].mesh;
    twin = contour::coincidentFaces(model, meshed);
  }
  std::vector<std::pair<std::size_t, std::size_t>> range(nf, {0, 0});
  for (int f = 0; f < nf; ++f) {
    if (!cs[f] || !meshes[f].ok()) continue;
    const size_t before = r.mesh.triangles.size(), quadsBefore = r.mesh.quads.size();
    if (twin[f] >= 0) {
      contour::shareFaceTriangles(model, f, range[twin[f]].first, range[twin[f]].second, meshes[f].mesh, r.mesh);
      r.faces[f].sharedWith = twin[f];
    } else {
      addFaceMesh(model, f, meshes[f].mesh, r.mesh);
      if (const int folded = cancelFoldedPairs(r.mesh, before))
        logDebug("face " + std::to_string(f + 1) + ": " + std::to_string(folded) + " folded triangles removed");
    }
    r.faces[f].quads = static_cast<int>(r.mesh.quads.size() - quadsBefore);
    range[f] = {before, r.mesh.triangles.size()};
    r.faces[f].triangles = static_cast<int>(r.mesh.triangles.size() - before);
    r.quality.merge(r.faces[f].quality);
  }
  r.times.emplace_back("assembly", since(t));
  return r;
}

}  // namespace aniso
