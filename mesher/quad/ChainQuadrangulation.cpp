#include "mesher/quad/ChainQuadrangulation.h"

#include <algorithm>
#include <map>

#include "mesher/predicates/Predicates.h"

namespace aniso::quad {
namespace {

using predicates::orient2d;

/// The outline of the chain's union, counter-clockwise, or empty when it is not one simple
/// loop through every corner of the chain.
std::vector<int> outline(const QuadMesh2d& mesh, std::span<const int> chain) {
  std::map<int, int> next;
  std::vector<int> corners;
  int edges = 0;
  for (int e : chain) {
    const int n = mesh.sides(e);
    for (int k = 0; k < n; ++k) {
      corners.push_back(mesh.corners[e][k]);
      if (std::find(chain.begin(), chain.end(), mesh.adj[e][k]) != chain.end()) continue;
      if (!next.emplace(mesh.corners[e][k], mesh.corners[e][(k + 1) % n]).second) return {};  // pinched
      ++edges;
    }
  }
  std::vector<int> loop;
  int v = next.begin()->first;
  do {
    loop.push_back(v);
    const auto it = next.find(v);
    if (it == next.end() || static_cast<int>(loop.size()) > edges) return {};
    v = it->second;
  } while (v != loop.front());
  if (static_cast<int>(loop.size()) != edges) return {};
  for (int c : corners)
    if (!next.count(c)) return {};  // a corner inside the union
  return loop;
}

struct Value {
  double worst = 2, sum = 0;
  bool better(const Value& o) const { return worst != o.worst ? worst > o.worst : sum > o.sum; }
};

class Search {
 public:
  Search(const QuadMesh2d& mesh, VertexMetrics& metrics, std::vector<int> loop, double minQuality)
      : mesh_(mesh), metrics_(metrics), p_(std::move(loop)), m_(static_cast<int>(p_.size())), min_(minQuality) {}

  /// The quads of the best quadrangulation, or empty.
  std::vector<Corners> run() {
    diagonals();
    best_.assign(m_ * m_, Value{-2, 0});
    choice_.assign(m_ * m_, {-1, -1});
    for (int i = 0; i + 1 < m_; ++i) best_[i * m_ + i + 1] = Value{};
    for (int len = 3; len < m_; len += 2)
      for (int i = 0; i + len < m_; ++i) solve(i, i + len);
    if (best_[m_ - 1].worst < min_) return {};
    std::vector<Corners> quads;
    collect(0, m_ - 1, quads);
    return quads;
  }

 private:
  const double* at(int i) const { return mesh_.uv[p_[i]].data(); }

  /// Segment (a, b) inside the polygon at a: strictly within the inner cone there.
  bool insideAt(int a, int b) const {
    const double* prev = at((a + m_ - 1) % m_);
    const double* next = at((a + 1) % m_);
    const bool convex = orient2d(prev, at(a), next) > 0;
    const bool leftOfNext = orient2d(at(a), next, at(b)) > 0, rightOfPrev = orient2d(at(a), at(b), prev) > 0;
    return convex ? (leftOfNext && rightOfPrev) : (leftOfNext || rightOfPrev);
  }

  bool crossesOutline(int a, int b) const {
    for (int c = 0; c < m_; ++c) {
      const int d = (c + 1) % m_;
      if (c == a || c == b || d == a || d == b) continue;
      const double o1 = orient2d(at(a), at(b), at(c)), o2 = orient2d(at(a), at(b), at(d));
      const double o3 = orient2d(at(c), at(d), at(a)), o4 = orient2d(at(c), at(d), at(b));
      if (o1 * o2 <= 0 && o3 * o4 <= 0) return true;  // crossing or touching
    }
    return false;
  }

  void diagonals() {
    chord_.assign(m_ * m_, 0);
    for (int a = 0; a < m_; ++a)
      for (int b = a + 1; b < m_; ++b) {
        const bool edge = b == a + 1 || (a == 0 && b == m_ - 1);
        const bool ok = edge || (insideAt(a, b) && insideAt(b, a) && !crossesOutline(a, b));
        chord_[a * m_ + b] = chord_[b * m_ + a] = ok;
      }
  }

  void solve(int i, int j) {
    Value& out = best_[i * m_ + j];
    for (int k = i + 1; k < j; k += 2) {
      if (!chord_[i * m_ + k] || best_[i * m_ + k].worst < min_) continue;
      for (int l = k + 1; l < j; l += 2) {
        if (!chord_[k * m_ + l] || !chord_[l * m_ + j]) continue;
        const Value& a = best_[i * m_ + k];
        const Value& b = best_[k * m_ + l];
        const Value& c = best_[l * m_ + j];
        if (b.worst < min_ || c.worst < min_) continue;
        const double q = elementQuality(mesh_, metrics_, Corners{p_[i], p_[k], p_[l], p_[j]});
        if (q < min_) continue;
        const Value v{std::min({q, a.worst, b.worst, c.worst}), q + a.sum + b.sum + c.sum};
        if (v.better(out)) {
          out = v;
          choice_[i * m_ + j] = {k, l};
        }
      }
    }
  }

  void collect(int i, int j, std::vector<Corners>& quads) const {
    if (j == i + 1) return;
    const auto [k, l] = choice_[i * m_ + j];
    quads.push_back({p_[i], p_[k], p_[l], p_[j]});
    collect(i, k, quads);
    collect(k, l, quads);
    collect(l, j, quads);
  }

  const QuadMesh2d& mesh_;
  VertexMetrics& metrics_;
  std::vector<int> p_;
  int m_;
  double min_;
  std::vector<std::uint8_t> chord_;
  std::vector<Value> best_;
  std::vector<std::pair<int, int>> choice_;
};

}  // namespace

bool quadrangulateChain(QuadMesh2d& mesh, VertexMetrics& metrics, std::span<const int> chain, const ChainOptions& o) {
  if (chain.size() < 2 || !mesh.isTriangle(chain.front()) || !mesh.isTriangle(chain.back())) return false;
  for (std::size_t i = 1; i + 1 < chain.size(); ++i)
    if (!mesh.isQuad(chain[i])) return false;
  std::vector<int> loop = outline(mesh, chain);
  const int m = static_cast<int>(loop.size());
  if (m < 4 || m % 2 == 1 || m > o.maxVertices) return false;
  // Start the loop at its smallest vertex: the result does not depend on the chain's order.
  std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
  const std::vector<Corners> quads = Search(mesh, metrics, std::move(loop), o.minQuality).run();
  if (quads.empty()) return false;
  mesh.replacePatch(chain, quads);
  return true;
}

}  // namespace aniso::quad
