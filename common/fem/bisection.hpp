// Newest-vertex bisection (Mitchell 1989; Binev-Dahmen-DeVore 2004) of a rectangle mesh: local
// refinement for the adaptive contact of chapter 10, conforming (no hanging node) and with
// angles bounded below whatever the number of refinements.
//
// Each triangle is stored as (v0, v1, v2), counter-clockwise, with its refinement edge v0-v1 and
// its newest vertex v2. Bisecting it at m = mid(v0, v1) gives (v2, v0, m) and (v1, v2, m): the
// new vertex m is the children's newest, and their refinement edges are the parent's other two
// edges. The descendants of a triangle fall into at most four similarity classes (Sewell 1972,
// Mitchell 1989), so the smallest angle is bounded by the initial mesh's alone.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <vector>

#include "common/fem/mesh.hpp"

namespace mortar {

class BisectionMesh {
 public:
  // The P1 mesh rectangle_mesh(spec) (jittered, graded or explicit nodes alike). Each triangle's
  // refinement edge is its cell's diagonal, shared with the other triangle of the cell, so the
  // first labelling is conforming.
  explicit BisectionMesh(const RectangleSpec& spec);
  const Mesh& mesh() const { return mesh_; }
  // Bisects every marked triangle (marked.size() == number of triangles) and as many others as
  // conformity needs (the closure): no hanging node. Side lists stay complete and ordered.
  void refine(const std::vector<bool>& marked);
  // The nodal field of the mesh before the last refine (components values per node, node-major:
  // index components*a + c, e.g. 2 for a displacement) on the current mesh: a new node takes the
  // mean of its edge's two ends (exact for a linear field; the prolongation of nested P1 spaces).
  // Before any refine, the identity.
  Eigen::VectorXd prolong(const Eigen::VectorXd& field, int components) const;
  // For each current triangle, the triangle of the mesh before the last refine it lies in.
  const std::vector<int>& parent_triangle() const { return parent_; }
  double min_angle_degrees() const;  // smallest interior angle over all triangles
  int generation_max() const;        // the most bisections any triangle has undergone
  // The bisections triangle t has undergone since the rectangle mesh.
  int generation(int t) const { return generation_[t]; }

 private:
  Mesh mesh_;                                // triangles as (v0, v1, v2): refinement edge v0-v1
  std::vector<int> generation_;              // per triangle
  std::vector<int> parent_;                  // per triangle: its triangle before the last refine
  std::vector<unsigned char> sides_of_;      // per node: bit s set when the node is on side s
  int old_num_nodes_ = 0;                    // nodes before the last refine
  std::vector<std::array<int, 2>> new_ends_;  // per new node of the last refine: its edge's ends
};

}  // namespace mortar
