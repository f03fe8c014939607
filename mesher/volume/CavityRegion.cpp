#include "mesher/volume/CavityRegion.h"

#include <numeric>

#include "mesher/delaunay3d/EdgeRing.h"
#include "mesher/predicates/Predicates.h"
#include "mesher/volume/MeshQueries.h"
#include "mesher/volume/Pipe.h"

namespace aniso::volume {

using del3d::TetId;
using del3d::TetMesh;
using del3d::VertexId;

std::uint64_t cavityEdgeKey(std::uint32_t a, std::uint32_t b) {
  if (a > b) std::swap(a, b);
  return (std::uint64_t{a} << 32) | b;
}

PatchEdges patchEdges(const std::vector<CavityFace>& tris, const std::vector<int>& patch) {
  PatchEdges e;
  for (const int t : patch)
    for (int j = 0; j < 3; ++j) {
      const std::uint64_t k = cavityEdgeKey(tris[t][j].index, tris[t][(j + 1) % 3].index);
      ++e.uses[k];
      e.triangle[k] = t;
    }
  return e;
}

int collectCavity(const TetMesh& m, const std::vector<CavityFace>& tris, const std::vector<int>& patch,
                  const PatchEdges& edges, Cavity& c) {
  std::vector<TetId> star;
  for (const int t : patch) {
    const FaceHandle fh = findFace(m, tris[t][0], tris[t][1], tris[t][2], star);
    if (!fh.valid()) continue;
    c.add(fh.tet);
    c.add(m.neighbour(fh.tet, fh.face));
  }
  Pipe pipe;
  del3d::EdgeRing ring;
  for (const int t : patch) {
    trianglePipe(m, tris[t][0], tris[t][1], tris[t][2], pipe);
    if (pipe.degenerate) return kCavityFailed;
    for (const EdgeRef& e : pipe.edges) {
      del3d::edgeRing(m, e.tet, e.i, e.j, ring);
      for (const TetId u : ring.tets) c.add(u);
    }
  }
  for (const auto& [key, uses] : edges.uses) {
    const VertexId a(static_cast<std::uint32_t>(key >> 32)), b(static_cast<std::uint32_t>(key & 0xFFFFFFFFu));
    const EdgeHandle present = findEdge(m, a, b, star);
    if (present.valid()) {
      // An edge inside I that is present: every tet around it goes, so that no face of
      // C's boundary touches it (the two sides meet only at the rim).
      if (uses > 1) {
        del3d::edgeRing(m, present.tet, present.i, present.j, ring);
        for (const TetId u : ring.tets) c.add(u);
      }
      continue;
    }
    segmentPipe(m, a, b, pipe);
    if (pipe.degenerate) return kCavityFailed;
    for (const FaceRef& f : pipe.faces) {
      c.add(f.tet);
      c.add(m.neighbour(f.tet, f.face));
    }
    for (const EdgeRef& e : pipe.edges) {
      del3d::edgeRing(m, e.tet, e.i, e.j, ring);
      for (const TetId u : ring.tets) c.add(u);
    }
  }
  return c.tets.empty() ? kCavityFailed : 0;
}

CavitySides splitSides(const TetMesh& m, const Cavity& c, const PatchEdges& edges, const std::vector<CavityFace>& tris) {
  CavitySides out;
  std::vector<CavityFace> faces;
  std::vector<TetId> next;
  for (const TetId t : c.tets)
    for (int i = 0; i < 4; ++i) {
      const TetId n = m.neighbour(t, i);
      if (n.valid() && c.in.count(n.index)) continue;
      if (!n.valid()) {  // the cavity reaches the hull: no room to work
        out.status = kCavityFailed;
        return out;
      }
      const auto& fv = del3d::kFaceVertex[i];
      faces.push_back({m.vertex(t, fv[0]), m.vertex(t, fv[1]), m.vertex(t, fv[2])});
      next.push_back(m.isConstrained(t, i) ? TetId() : n);
    }
  std::vector<int> parent(faces.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  std::map<std::uint64_t, std::vector<int>> faceEdges;
  for (std::size_t f = 0; f < faces.size(); ++f)
    for (int j = 0; j < 3; ++j)
      faceEdges[cavityEdgeKey(faces[f][j].index, faces[f][(j + 1) % 3].index)].push_back(static_cast<int>(f));
  for (const auto& [key, list] : faceEdges) {
    if (edges.isRim(key)) continue;  // a rim edge separates the sides
    for (std::size_t k = 1; k < list.size(); ++k) parent[find(list[k])] = find(list[0]);
  }
  // Side of each group from a face on a rim edge: +1 outer, -1 inner.
  std::map<int, int> side;
  for (const auto& [key, list] : faceEdges) {
    if (!edges.isRim(key)) continue;
    const CavityFace& t = tris[edges.triangle.at(key)];
    for (const int f : list) {
      VertexId q;
      for (const VertexId v : faces[f])
        if ((key >> 32) != v.index && (key & 0xFFFFFFFFu) != v.index) q = v;
      const double o = predicates::orient3d(m.coords(t[0]), m.coords(t[1]), m.coords(t[2]), m.coords(q));
      if (o == 0) continue;
      const int s = o > 0 ? 1 : -1;
      auto [it, fresh] = side.emplace(find(f), s);
      if (!fresh && it->second != s) {  // a group on both sides: not separable here
        out.status = kCavitySidesMixed;
        return out;
      }
    }
  }
  for (std::size_t f = 0; f < faces.size(); ++f) {
    const auto it = side.find(find(static_cast<int>(f)));
    if (it == side.end()) {  // a group touching no rim edge
      out.status = kCavityFailed;
      return out;
    }
    (it->second > 0 ? out.outer : out.inner).push_back(faces[f]);
    (it->second > 0 ? out.outerNext : out.innerNext).push_back(next[f]);
  }
  return out;
}

void growSide(const TetMesh& m, const std::vector<CavityFace>& faces, const std::vector<TetId>& next,
              const PatchEdges& edges, const Vec3& start, double margin, Cavity& c) {
  auto touchesRim = [&](TetId t) {
    for (int i = 0; i < 4; ++i)
      for (int j = i + 1; j < 4; ++j)
        if (edges.isRim(cavityEdgeKey(m.vertex(t, i).index, m.vertex(t, j).index))) return true;
    return false;
  };
  Vec3 q;
  relaxIntoKernel(m, faces, start, margin, q);
  std::size_t added = 0;
  for (std::size_t f = 0; f < next.size(); ++f) {
    if (!next[f].valid() || touchesRim(next[f])) continue;
    if (predicates::orient3d(m.coords(faces[f][0]), m.coords(faces[f][1]), m.coords(faces[f][2]), q.data()) > 0)
      continue;
    c.add(next[f]);
    ++added;
  }
  if (added == 0)  // nothing hides the point: take the whole next layer
    for (const TetId n : next)
      if (n.valid() && !touchesRim(n)) c.add(n);
}

}  // namespace aniso::volume
