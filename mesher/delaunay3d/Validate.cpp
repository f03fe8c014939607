#include "mesher/delaunay3d/Validate.h"

#include <algorithm>
#include <array>
#include <string>

#include "mesher/delaunay3d/TransformPoint.h"
#include "mesher/predicates/Predicates.h"

namespace aniso::del3d {
namespace {

struct Report {
  std::vector<std::string> problems;
  std::size_t max;
  bool full() const { return problems.size() >= max; }
  void add(std::string s) {
    if (!full()) problems.push_back(std::move(s));
  }
};

std::string tetName(TetId t) { return "tet " + std::to_string(t.index); }

void checkFreeList(const TetMesh& mesh, Report& r) {
  std::vector<char> onList(mesh.tetSlots(), 0);
  std::size_t free = 0;
  // each slot is checked before nextFree reads it (a live slot is not nextFree's to read)
  for (std::uint32_t f = mesh.freeHead(); f != kNone;) {
    if (f >= mesh.tetSlots()) return r.add("free list points outside the slots: " + std::to_string(f));
    if (onList[f]) return r.add("free list has a cycle at slot " + std::to_string(f));
    if (mesh.isAlive(TetId(f))) return r.add("free list holds the live " + tetName(TetId(f)));
    onList[f] = 1;
    ++free;
    f = mesh.nextFree(TetId(f));
  }
  if (free + mesh.numTets() != mesh.tetSlots())
    r.add("free (" + std::to_string(free) + ") + live (" + std::to_string(mesh.numTets()) +
          ") != slots (" + std::to_string(mesh.tetSlots()) + ")");
}

std::array<std::uint32_t, 3> sortedFace(const std::uint32_t* v, int i) {
  std::array<std::uint32_t, 3> f = {v[kFaceVertex[i][0]], v[kFaceVertex[i][1]], v[kFaceVertex[i][2]]};
  std::sort(f.begin(), f.end());
  return f;
}

void checkTet(const TetMesh& mesh, TetId t, Report& r) {
  const std::uint32_t* v = mesh.tetVertices(t);
  for (int i = 0; i < 4; ++i) {
    if (v[i] >= mesh.numVertices()) return r.add(tetName(t) + " has a missing vertex");
    for (int j = 0; j < i; ++j)
      if (v[i] == v[j]) return r.add(tetName(t) + " repeats vertex " + std::to_string(v[i]));
  }
  if (mesh.flags(t) & (TetMesh::kMarkA | TetMesh::kMarkB)) r.add(tetName(t) + " has a scratch mark left set");
  for (int i = 0; i < 4; ++i) {
    const std::uint32_t code = mesh.adjacentCode(t, i);
    if (code == kNone) continue;
    const TetId n = codeTet(code);
    const int j = codeFace(code);
    if (!mesh.isAlive(n)) {
      r.add(tetName(t) + " face " + std::to_string(i) + " points at a dead slot");
      continue;
    }
    if (mesh.adjacentCode(n, j) != faceCode(t, i))
      r.add(tetName(t) + " face " + std::to_string(i) + ": " + tetName(n) + " does not point back");
    else if (sortedFace(v, i) != sortedFace(mesh.tetVertices(n), j))
      r.add(tetName(t) + " face " + std::to_string(i) + " and " + tetName(n) + " face " + std::to_string(j) +
            " have different vertices");
    else if (mesh.isConstrained(t, i) != mesh.isConstrained(n, j))
      r.add(tetName(t) + " face " + std::to_string(i) + ": constrained bit differs across the face");
  }
}

void checkVertexTets(const TetMesh& mesh, Report& r) {
  std::vector<char> used(mesh.numVertices(), 0);
  for (std::uint32_t k = 0; k < mesh.tetSlots(); ++k) {
    if (!mesh.isAlive(TetId(k))) continue;
    const std::uint32_t* v = mesh.tetVertices(TetId(k));
    for (int i = 0; i < 4; ++i)
      if (v[i] < used.size()) used[v[i]] = 1;
  }
  for (std::uint32_t k = 0; k < mesh.numVertices() && !r.full(); ++k) {
    const VertexId v(k);
    const TetId t = mesh.vertexTet(v);
    if (!t.valid()) {
      if (used[k]) r.add("vertex " + std::to_string(k) + " is in tets but has no vertex tet");
    } else if (!mesh.isAlive(t) || mesh.localIndex(t, v) < 0) {
      r.add("vertex " + std::to_string(k) + ": its vertex tet does not contain it");
    }
  }
}

void checkGeometry(const TetMesh& mesh, const ValidateOptions& o, Report& r) {
  const bool identity = o.transform.isIdentity(0.0);
  std::vector<double> mx;
  if (o.checkDelaunay && !identity) {
    mx.resize(mesh.xyz().size());
    for (std::size_t k = 0; k < mesh.numVertices(); ++k) transformPoint(o.transform, &mesh.xyz()[3 * k], &mx[3 * k]);
  }
  const double* base = identity ? mesh.xyz().data() : mx.data();
  for (std::uint32_t k = 0; k < mesh.tetSlots() && !r.full(); ++k) {
    const TetId t(k);
    if (!mesh.isAlive(t)) continue;
    const std::uint32_t* v = mesh.tetVertices(t);
    if (o.checkOrientation &&
        predicates::orient3d(mesh.coords(VertexId(v[0])), mesh.coords(VertexId(v[1])), mesh.coords(VertexId(v[2])),
                             mesh.coords(VertexId(v[3]))) <= 0)
      r.add(tetName(t) + " is not positively oriented");
    if (!o.checkDelaunay) continue;
    const double* a = base + 3 * std::size_t{v[0]};
    const double* b = base + 3 * std::size_t{v[1]};
    const double* c = base + 3 * std::size_t{v[2]};
    const double* d = base + 3 * std::size_t{v[3]};
    const double s = identity ? 1.0 : predicates::orient3d(a, b, c, d);
    for (int i = 0; i < 4; ++i) {
      const std::uint32_t code = mesh.adjacentCode(t, i);
      if (code == kNone || mesh.isConstrained(t, i) || (code >> 2) < k) continue;
      const std::uint32_t e = mesh.tetVertices(codeTet(code))[codeFace(code)];
      const double in = predicates::insphere(a, b, c, d, base + 3 * std::size_t{e});
      if (s == 0 || (s > 0 ? in > 0 : in < 0))
        r.add(tetName(t) + " face " + std::to_string(i) + ": vertex " + std::to_string(e) +
              " is inside the circumsphere (not Delaunay)");
    }
  }
}

}  // namespace

std::vector<std::string> validate(const TetMesh& mesh, const ValidateOptions& options) {
  Report r{{}, options.maxProblems};
  checkFreeList(mesh, r);
  for (std::uint32_t k = 0; k < mesh.tetSlots() && !r.full(); ++k)
    if (mesh.isAlive(TetId(k))) checkTet(mesh, TetId(k), r);
  if (r.problems.empty()) checkVertexTets(mesh, r);
  if (r.problems.empty()) checkGeometry(mesh, options, r);
  return r.problems;
}

}  // namespace aniso::del3d

