#include "common/fem/bisection.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <utility>

namespace mortar {

namespace {
using Triangle = std::array<int, 3>;

// The edges of a mesh numbered in order of first appearance, found by their two end nodes: an
// open-addressing hash table (linear probing, Fibonacci hashing of the packed pair). An ordered
// map per edge would cost more than the whole refinement; this keeps refine O(triangles).
class EdgeTable {
 public:
  explicit EdgeTable(std::size_t max_edges) {
    int bits = 4;
    while ((std::size_t{1} << bits) < 2 * max_edges) ++bits;  // at most half full: short probes
    shift_ = 64 - bits;
    keys_.assign(std::size_t{1} << bits, kEmpty);
    ids_.resize(keys_.size());
  }
  // Edge a-b's number, the next one the first time the edge is met.
  int insert(int a, int b) {
    if (a > b) std::swap(a, b);
    const std::uint64_t key = (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
    const std::size_t mask = keys_.size() - 1;
    for (std::size_t slot = (key * 0x9E3779B97F4A7C15ull) >> shift_;; slot = (slot + 1) & mask) {
      if (keys_[slot] == key) return ids_[slot];
      if (keys_[slot] == kEmpty) {
        if (static_cast<std::size_t>(count_) + 1 >= keys_.size())  // never: sized for every edge
          throw std::logic_error("BisectionMesh: edge table full");
        keys_[slot] = key;
        ids_[slot] = count_;
        return count_++;
      }
    }
  }
  int size() const { return count_; }

 private:
  static constexpr std::uint64_t kEmpty = ~std::uint64_t{0};  // no pair of int nodes packs to it
  std::vector<std::uint64_t> keys_;
  std::vector<int> ids_;
  int shift_ = 0, count_ = 0;
};

// Each triangle's three edges (local edge k joins vertices k and k+1: edge 0 is the refinement
// edge), each edge's ends and the (one or two) triangles it belongs to (-1 for none).
struct Edges {
  std::vector<std::array<int, 3>> of_triangle;
  std::vector<std::array<int, 2>> ends, triangles;
};

// A conforming mesh of T triangles whose boundary has B edges has (3 T + B) / 2 edges: each
// interior edge is counted by two triangles, each boundary edge by one.
Edges number_edges(const Mesh& mesh) {
  const auto& triangles = mesh.triangles;
  std::size_t boundary = 0;
  for (const auto& side : mesh.side_nodes) boundary += side.empty() ? 0 : side.size() - 1;
  const std::size_t count = (3 * triangles.size() + boundary) / 2;
  Edges edges;
  EdgeTable table(count);
  edges.of_triangle.resize(triangles.size());
  edges.ends.reserve(count);
  edges.triangles.reserve(count);
  for (std::size_t t = 0; t < triangles.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      const int a = triangles[t][k], b = triangles[t][(k + 1) % 3];
      const int e = table.insert(a, b);
      if (e == static_cast<int>(edges.ends.size())) {
        edges.ends.push_back({a, b});
        edges.triangles.push_back({static_cast<int>(t), -1});
      } else {
        edges.triangles[e][1] = static_cast<int>(t);
      }
      edges.of_triangle[t][k] = e;
    }
  return edges;
}

// The closure (Binev-Dahmen-DeVore 2004, section 4): the refinement edge of each marked triangle
// is marked, then the refinement edge of every triangle with a marked edge, until nothing
// changes. Then a triangle with any marked edge has its refinement edge marked, so bisecting it
// and its children at marked edges leaves no hanging node. A stack of newly marked edges visits
// each edge once: O(triangles).
std::vector<char> closure(const Edges& edges, const std::vector<bool>& marked) {
  std::vector<char> edge_marked(edges.ends.size(), 0);
  std::vector<int> fresh;
  auto mark = [&](int e) {
    if (!edge_marked[e]) {
      edge_marked[e] = 1;
      fresh.push_back(e);
    }
  };
  for (std::size_t t = 0; t < marked.size(); ++t)
    if (marked[t]) mark(edges.of_triangle[t][0]);
  while (!fresh.empty()) {
    const int e = fresh.back();
    fresh.pop_back();
    for (int t : edges.triangles[e])
      if (t >= 0) mark(edges.of_triangle[t][0]);
  }
  return edge_marked;
}

// The triangles of the refined mesh, with their generations and parents.
struct Children {
  std::vector<Triangle> triangles;
  std::vector<int> generation, parent;
};

// Bisects t = (v0, v1, v2) at its refinement edge's midpoint mid[0] (if that edge is marked)
// into (v2, v0, m) and (v1, v2, m), then each child at its own refinement edge, the parent's
// edge 2-0 or 1-2, with that edge's midpoint mid[2] or mid[1]. The children's new edges are
// never marked: a triangle is bisected at most three times in one refine.
void bisect(const Triangle& t, const std::array<int, 3>& mid, int generation, int parent, Children& out) {
  if (mid[0] < 0) {
    out.triangles.push_back(t);
    out.generation.push_back(generation);
    out.parent.push_back(parent);
    return;
  }
  const int m = mid[0];
  bisect({t[2], t[0], m}, {mid[2], -1, -1}, generation + 1, parent, out);
  bisect({t[1], t[2], m}, {mid[1], -1, -1}, generation + 1, parent, out);
}

// Rotates a triangle (keeping its orientation) so that its edge {a, b} comes first.
Triangle with_first_edge(const Triangle& t, int a, int b) {
  for (int k = 0; k < 3; ++k) {
    const int p = t[k], q = t[(k + 1) % 3];
    if ((p == a && q == b) || (p == b && q == a)) return {p, q, t[(k + 2) % 3]};
  }
  throw std::logic_error("BisectionMesh: the two triangles of a cell share no edge");
}

// The two vertices triangles s and t have in common (the diagonal of their cell).
std::pair<int, int> shared_edge(const Triangle& s, const Triangle& t) {
  std::vector<int> common;
  for (int a : s)
    if (std::find(t.begin(), t.end(), a) != t.end()) common.push_back(a);
  if (common.size() != 2) throw std::logic_error("BisectionMesh: the two triangles of a cell share no edge");
  return {common[0], common[1]};
}
}  // namespace

BisectionMesh::BisectionMesh(const RectangleSpec& spec) : mesh_(rectangle_mesh(spec)) {
  // rectangle_mesh lists the two triangles of each cell one after the other; their shared
  // diagonal becomes the refinement edge of both, so matching refinement edges pair up.
  auto& triangles = mesh_.triangles;
  for (std::size_t t = 0; t + 1 < triangles.size(); t += 2) {
    const auto [a, b] = shared_edge(triangles[t], triangles[t + 1]);
    triangles[t] = with_first_edge(triangles[t], a, b);
    triangles[t + 1] = with_first_edge(triangles[t + 1], a, b);
  }
  generation_.assign(triangles.size(), 0);
  parent_.resize(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t) parent_[t] = static_cast<int>(t);
  sides_of_.assign(mesh_.nodes.size(), 0);
  for (int s = 0; s < 4; ++s)
    for (int a : mesh_.side_nodes[s]) sides_of_[a] |= 1u << s;
  old_num_nodes_ = mesh_.num_nodes();
}

void BisectionMesh::refine(const std::vector<bool>& marked) {
  if (marked.size() != mesh_.triangles.size())
    throw std::invalid_argument("BisectionMesh::refine: " + std::to_string(marked.size()) +
                                " marks for a mesh of " + std::to_string(mesh_.triangles.size()) +
                                " triangles (one mark per triangle)");
  const Edges edges = number_edges(mesh_);
  const std::vector<char> edge_marked = closure(edges, marked);

  // a node at the midpoint of each marked edge, appended in edge order; on side s exactly when
  // both ends are (a segment between two points of a straight side lies on it)
  old_num_nodes_ = mesh_.num_nodes();
  new_ends_.clear();
  std::vector<int> midpoint(edges.ends.size(), -1);
  unsigned char new_sides = 0;
  for (std::size_t e = 0; e < edges.ends.size(); ++e) {
    if (!edge_marked[e]) continue;
    const auto [a, b] = edges.ends[e];
    midpoint[e] = mesh_.num_nodes();
    mesh_.nodes.push_back(0.5 * (mesh_.nodes[a] + mesh_.nodes[b]));
    sides_of_.push_back(sides_of_[a] & sides_of_[b]);
    new_sides |= sides_of_.back();
    new_ends_.push_back({a, b});
  }

  Children children;
  children.triangles.reserve(mesh_.triangles.size() + 2 * new_ends_.size());
  children.generation.reserve(children.triangles.capacity());
  children.parent.reserve(children.triangles.capacity());
  for (std::size_t t = 0; t < mesh_.triangles.size(); ++t) {
    const auto& e = edges.of_triangle[t];
    bisect(mesh_.triangles[t], {midpoint[e[0]], midpoint[e[1]], midpoint[e[2]]}, generation_[t],
           static_cast<int>(t), children);
  }
  mesh_.triangles = std::move(children.triangles);
  generation_ = std::move(children.generation);
  parent_ = std::move(children.parent);

  // new side nodes go to their lists, which are sorted again along the side (x for bottom and
  // top, y for left and right)
  for (int s = 0; s < 4; ++s) {
    if (!(new_sides & (1u << s))) continue;
    auto& list = mesh_.side_nodes[s];
    for (int a = old_num_nodes_; a < mesh_.num_nodes(); ++a)
      if (sides_of_[a] & (1u << s)) list.push_back(a);
    const int axis = (s == static_cast<int>(Side::bottom) || s == static_cast<int>(Side::top)) ? 0 : 1;
    std::sort(list.begin(), list.end(),
              [&](int a, int b) { return mesh_.nodes[a][axis] < mesh_.nodes[b][axis]; });
  }
}

Eigen::VectorXd BisectionMesh::prolong(const Eigen::VectorXd& field, int components) const {
  if (components < 1 || field.size() != static_cast<Eigen::Index>(components) * old_num_nodes_)
    throw std::invalid_argument("BisectionMesh::prolong: a field of " + std::to_string(field.size()) +
                                " values with " + std::to_string(components) +
                                " components per node, the mesh before the last refine has " +
                                std::to_string(old_num_nodes_) + " nodes");
  Eigen::VectorXd out(static_cast<Eigen::Index>(components) * mesh_.num_nodes());
  out.head(field.size()) = field;
  // in creation order, so a midpoint of midpoints finds its ends already set
  for (std::size_t k = 0; k < new_ends_.size(); ++k) {
    const Eigen::Index n = old_num_nodes_ + static_cast<Eigen::Index>(k);
    const auto [a, b] = new_ends_[k];
    for (int c = 0; c < components; ++c)
      out[components * n + c] = 0.5 * (out[components * a + c] + out[components * b + c]);
  }
  return out;
}

double BisectionMesh::min_angle_degrees() const { return mortar::min_angle_degrees(mesh_); }

int BisectionMesh::generation_max() const {
  return generation_.empty() ? 0 : *std::max_element(generation_.begin(), generation_.end());
}

}  // namespace mortar
