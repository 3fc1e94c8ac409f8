// Nested iteration for chapter 9: each level starts from the level below's answer.
//
// The semismooth Newton method's steps are the active sets it visits. From a cold start (u = 0,
// no node in contact) it walks the set out from nothing, a few nodes at each edge of the zone
// per step, and a finer mesh has more nodes to walk (7 steps at 0.1M unknowns, 23 at 13.6M). From
// the coarser level's answer the set is nearly right at once, as in chapter 6's nested start and
// PETSc's grid sequencing (SNESVI, src/snes/tutorials/ex9.c). Two things are carried up:
//
//   - the displacement, as its P1 interpolant: each rank reads the coarse values of the cell
//     rows under its own band (one scatter of a contiguous range per body), so no rank holds
//     the coarse field whole;
//   - the multipliers along Gamma_c, as a piecewise-linear function of x (each lambda_i is a
//     pressure, h-independent: the rows of B carry the element length).
//
// The first active set is then chapter 6's rule evaluated on the start, lambda~_i + c_i w~_i > 0,
// as chapter 10 does between its adaptive steps.
#pragma once

#include <petscvec.h>

#include <vector>

#include "rank_part.hpp"

namespace chapter09 {

// The answer of the level below, kept while the next level is solved.
struct CoarseAnswer {
  RowSplit split;
  Vec u = nullptr;                // its displacement, distributed on its own rows
  std::vector<double> x, lambda;  // each multiplier's node along Gamma_c and its value (every rank)
  CoarseAnswer(RowSplit s, Vec displacement, std::vector<double> x_rows, std::vector<double> lambda_rows);
  ~CoarseAnswer();
  CoarseAnswer(const CoarseAnswer&) = delete;
  CoarseAnswer& operator=(const CoarseAnswer&) = delete;
};

// The coarse displacement's P1 interpolant at the nodes this rank owns, in a vector laid out as
// `like` (this level's rows). The coarse cell of a node is found from its position in the
// coarse rectangle; with jitter the coarse nodes are not where the cell grid puts them, and the
// start is a little off (a start only: the answer does not depend on it).
void interpolate_displacement(const CoarseAnswer& coarse, const Part& own, Vec like_and_out);

// The coarse multipliers, linear in x between their nodes (constant beyond the ends), at x.
std::vector<double> interpolate_multipliers(const CoarseAnswer& coarse, const std::vector<double>& x);

}  // namespace chapter09
