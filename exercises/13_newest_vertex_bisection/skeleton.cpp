#include "exercise.hpp"

namespace exercise {

void bisect_with_closure(std::vector<Eigen::Vector2d>& nodes, std::vector<std::array<int, 3>>& triangles, int t) {
  // Your code here: find the triangle across t's refinement edge; refine it first if that edge
  // is not its refinement edge too; then bisect t and (if there is one) that neighbour at one
  // new midpoint. As it stands the mesh is left as it was.
  (void)nodes;
  (void)triangles;
  (void)t;
}

}  // namespace exercise
