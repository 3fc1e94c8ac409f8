#include "exercise.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace exercise {

namespace {
using Triangle = std::array<int, 3>;

// The triangle other than t that has the edge a-b, or -1 where a-b is on the boundary. A search
// through the whole list: enough for the meshes of this exercise.
int across(const std::vector<Triangle>& triangles, int t, int a, int b) {
  for (int s = 0; s < static_cast<int>(triangles.size()); ++s) {
    if (s == t) continue;
    const auto& tri = triangles[s];
    for (int k = 0; k < 3; ++k) {
      const int p = tri[k], q = tri[(k + 1) % 3];
      if ((p == a && q == b) || (p == b && q == a)) return s;
    }
  }
  return -1;
}

// Whether a-b is triangle s's refinement edge (v0-v1), in either direction.
bool refines_at(const Triangle& s, int a, int b) { return (s[0] == a && s[1] == b) || (s[0] == b && s[1] == a); }

// (v0, v1, v2) becomes (v2, v0, m) in its place and (v1, v2, m) at the end of the list.
void bisect(std::vector<Triangle>& triangles, int s, int m) {
  const Triangle tri = triangles[s];
  triangles[s] = {tri[2], tri[0], m};
  triangles.push_back({tri[1], tri[2], m});
}
}  // namespace

void bisect_with_closure(std::vector<Eigen::Vector2d>& nodes, std::vector<Triangle>& triangles, int t) {
  if (t < 0 || t >= static_cast<int>(triangles.size()))
    throw std::invalid_argument("bisect_with_closure: triangle " + std::to_string(t) + " of a mesh of " +
                                std::to_string(triangles.size()) + " triangles");
  // The chain t = c_0, c_1, ...: c_{i+1} is the triangle across c_i's refinement edge, for as
  // long as that edge is not c_{i+1}'s refinement edge too. It ends at a boundary edge or at a
  // neighbour with the same refinement edge. Nothing is bisected until it is known.
  std::vector<int> chain{t};
  for (;;) {
    const Triangle& last = triangles[chain.back()];
    const int n = across(triangles, chain.back(), last[0], last[1]);
    if (n < 0 || refines_at(triangles[n], last[0], last[1])) break;
    if (std::find(chain.begin(), chain.end(), n) != chain.end())
      throw std::invalid_argument("bisect_with_closure: the refinement edges from triangle " + std::to_string(t) +
                                  " go round in a circle back to triangle " + std::to_string(n) +
                                  ": the closure would never end");
    chain.push_back(n);
  }
  // From the end of the chain back to t: c_i and the triangle across its refinement edge (after
  // the bisection of c_{i+1}, the child of c_{i+1} that holds that edge, with it as refinement
  // edge) are bisected at one new midpoint.
  for (auto it = chain.rbegin(); it != chain.rend(); ++it) {
    const int c = *it;
    const int a = triangles[c][0], b = triangles[c][1];
    const int n = across(triangles, c, a, b);
    const int m = static_cast<int>(nodes.size());
    nodes.push_back(0.5 * (nodes[a] + nodes[b]));
    bisect(triangles, c, m);
    if (n >= 0) bisect(triangles, n, m);
  }
}

}  // namespace exercise
