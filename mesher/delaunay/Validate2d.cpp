#include "mesher/delaunay/Validate2d.h"

#include <algorithm>
#include <cstdint>
#include <sstream>

#include "mesher/delaunay/PlaneTransform.h"
#include "mesher/predicates/Predicates.h"

namespace aniso::del2d {
namespace {

class Report {
 public:
  Report(std::vector<std::string>& out, std::size_t max) : out_(out), max_(max) {}
  bool full() const { return out_.size() >= max_; }
  template <class... A>
  void add(const A&... parts) {
    if (full()) return;
    std::ostringstream s;
    (s << ... << parts);
    out_.push_back(s.str());
  }

 private:
  std::vector<std::string>& out_;
  std::size_t max_;
};

void checkFreeList(const Triangulation2d& tri, Report& r) {
  std::size_t inList = 0;
  std::vector<std::uint8_t> seen(tri.triangleSlots(), 0);
  // each slot is checked before nextFree reads it (a live slot is not nextFree's to read)
  for (std::uint32_t k = tri.freeHead(); k != kNone;) {
    if (k >= tri.triangleSlots()) return r.add("free list: slot ", k, " out of range");
    if (seen[k]) return r.add("free list: cycle at slot ", k);
    if (tri.isAlive(TriId(k))) return r.add("free list: live triangle ", k);
    seen[k] = 1;
    ++inList;
    k = tri.nextFree(TriId(k));
  }
  const std::size_t freeSlots = tri.triangleSlots() - tri.numTriangles();
  if (inList != freeSlots) r.add("free list: ", inList, " slots listed, ", freeSlots, " free");
  std::size_t alive = 0;
  for (std::uint32_t k = 0; k < tri.triangleSlots(); ++k) alive += tri.isAlive(TriId(k));
  if (alive != tri.numTriangles()) r.add("live count ", tri.numTriangles(), " but ", alive, " live slots");
}

void checkTriangle(const Triangulation2d& tri, TriId t, Report& r) {
  const std::uint32_t* tv = tri.triVertices(t);
  for (int i = 0; i < 3; ++i)
    if (tv[i] >= tri.numVertices()) return r.add("triangle ", t.index, ": vertex ", tv[i], " does not exist");
  if (tv[0] == tv[1] || tv[1] == tv[2] || tv[0] == tv[2])
    return r.add("triangle ", t.index, ": repeated vertex");
  if (predicates::orient2d(tri.coords(VertexId(tv[0])), tri.coords(VertexId(tv[1])), tri.coords(VertexId(tv[2]))) <= 0)
    r.add("triangle ", t.index, " (", tv[0], ",", tv[1], ",", tv[2], ") is not counter-clockwise");
  if (tri.flags(t) & ~Triangulation2d::kConstrainedMask) r.add("triangle ", t.index, ": scratch marks left set");
  for (int i = 0; i < 3; ++i) {
    const TriId u = tri.neighbour(t, i);
    if (!u.valid()) continue;
    if (u == t) {
      r.add("triangle ", t.index, " is its own neighbour");
      continue;
    }
    if (!tri.isAlive(u)) {
      r.add("triangle ", t.index, ": neighbour ", i, " (", u.index, ") is not live");
      continue;
    }
    const int j = tri.neighbourIndex(u, t);
    if (j < 0) {
      r.add("triangle ", t.index, ": neighbour ", u.index, " does not point back");
      continue;
    }
    const VertexId b = tri.vertex(t, kNext[i]), c = tri.vertex(t, kPrev[i]);
    if (tri.vertex(u, kNext[j]) != c || tri.vertex(u, kPrev[j]) != b)
      r.add("triangles ", t.index, " and ", u.index, " do not share edge (", b.index, ",", c.index, ")");
    if (tri.isConstrained(t, i) != tri.isConstrained(u, j))
      r.add("edge (", b.index, ",", c.index, "): constrained bit differs between ", t.index, " and ", u.index);
  }
}

void checkEdgesAndVertices(const Triangulation2d& tri, Report& r) {
  std::vector<std::uint64_t> edges;
  edges.reserve(3 * tri.numTriangles());
  std::vector<std::uint8_t> used(tri.numVertices(), 0);
  for (std::uint32_t k = 0; k < tri.triangleSlots(); ++k) {
    if (!tri.isAlive(TriId(k))) continue;
    const std::uint32_t* tv = tri.triVertices(TriId(k));
    for (int i = 0; i < 3; ++i) {
      if (tv[i] >= tri.numVertices()) return;  // reported by checkTriangle
      used[tv[i]] = 1;
      edges.push_back((std::uint64_t{tv[i]} << 32) | tv[kNext[i]]);
    }
  }
  std::sort(edges.begin(), edges.end());
  for (std::size_t k = 1; k < edges.size(); ++k)
    if (edges[k] == edges[k - 1])
      r.add("directed edge (", edges[k] >> 32, ",", edges[k] & 0xffffffffu, ") is in two triangles");
  for (std::uint32_t v = 0; v < tri.numVertices(); ++v) {
    const TriId t = tri.vertexTriangle(VertexId(v));
    if (t.valid()) {
      if (!tri.isAlive(t)) r.add("vertex ", v, ": links to dead triangle ", t.index);
      else if (tri.localIndex(t, VertexId(v)) < 0) r.add("vertex ", v, ": linked triangle ", t.index, " lacks it");
    } else if (used[v]) {
      r.add("vertex ", v, ": used by triangles but linked to none");
    }
  }
}

void checkDelaunay(const Triangulation2d& tri, const PlaneTransform& m, Report& r) {
  for (std::uint32_t k = 0; k < tri.triangleSlots() && !r.full(); ++k) {
    const TriId t(k);
    if (!tri.isAlive(t)) continue;
    const std::uint32_t* tv = tri.triVertices(t);
    for (int i = 0; i < 3; ++i) {
      const TriId u = tri.neighbour(t, i);
      if (!u.valid() || tri.isConstrained(t, i) || u.index < k) continue;  // each edge once
      const int j = tri.neighbourIndex(u, t);
      if (j < 0) continue;
      const VertexId d = tri.vertex(u, j);
      if (m.inCircle(tri.point(VertexId(tv[0])), tri.point(VertexId(tv[1])), tri.point(VertexId(tv[2])),
                     m.apply(tri.point(d))) > 0)
        r.add("edge (", tv[kNext[i]], ",", tv[kPrev[i]], ") of triangles ", k, "/", u.index,
              " is not Delaunay: vertex ", d.index, " inside the circumcircle");
    }
  }
}

}  // namespace

std::vector<std::string> validate(const Triangulation2d& tri, const ValidateOptions& options) {
  std::vector<std::string> problems;
  Report r(problems, options.maxProblems);
  checkFreeList(tri, r);
  for (std::uint32_t k = 0; k < tri.triangleSlots() && !r.full(); ++k)
    if (tri.isAlive(TriId(k))) checkTriangle(tri, TriId(k), r);
  checkEdgesAndVertices(tri, r);
  if (options.delaunay) {
    const PlaneTransform m(options.transform);
    if (m.orientation() == 0) r.add("Delaunay check: the transformation is singular");
    else checkDelaunay(tri, m, r);
  }
  return problems;
}

}  // namespace aniso::del2d
