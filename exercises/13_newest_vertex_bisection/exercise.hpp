// Exercise 13: newest-vertex bisection of one triangle of a general triangle mesh, with the
// closure that keeps the mesh conforming (chapter 10).
#pragma once

#include <Eigen/Dense>
#include <array>
#include <vector>

namespace exercise {

// A conforming mesh of counter-clockwise triangles, each stored as (v0, v1, v2): its refinement
// edge is v0-v1 and its newest vertex v2. Bisecting a triangle (v0, v1, v2) puts a new node m
// at the midpoint of v0 and v1 and replaces the triangle by its two children (v2, v0, m) and
// (v1, v2, m).
//
// Bisects triangle t, and before it every triangle that must be bisected so that the mesh stays
// conforming (no node inside an edge of another triangle): where the triangle across a refinement
// edge does not have that edge as its own refinement edge, it is refined first, in the same way.
// An edge on the boundary has no triangle across it.
//
// On return: the nodes present before keep their indices and the new nodes are appended, one per
// bisected edge; the triangles that were not bisected keep their indices and their vertices; the
// children fill the places of the bisected triangles and new places at the end, in any order,
// each with its vertices in the order given above (which labels it).
//
// Throws std::invalid_argument, with the mesh unchanged, when t is not a triangle index, or when
// the closure comes back to a triangle that is waiting for its neighbour to be refined (the
// refinement edges then go round in a circle and the closure would never end).
void bisect_with_closure(std::vector<Eigen::Vector2d>& nodes, std::vector<std::array<int, 3>>& triangles, int t);

}  // namespace exercise
