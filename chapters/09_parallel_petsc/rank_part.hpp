// Step 2 of chapter 9: who owns what, and each rank's part of the two bodies, built alone.
//
// The unknowns keep the course's global numbering (body 1's nodes row by row from Gamma_c up,
// then body 2's from its bottom up), and the ranks split it into consecutive ranges of whole
// cell rows: rank r integrates the triangles of its cell rows and owns their nodes, except the
// row above its band, which belongs to the next rank (a body's top row goes with its last
// cell row). A band is about n / P unknowns plus one row of nodes, so no rank ever holds the
// whole mesh: rectangle_band builds the band alone, jitter included. The ranges are balanced
// by nodes, to within one row.
//
// The contact line is built the same way, from the two cell rows that touch Gamma_c (body 1's
// first, body 2's last): small, one-dimensional, and the same on every rank.
#pragma once

#include <petscsys.h>

#include <array>
#include <utility>
#include <vector>

#include "common/contact/contact_scenes.hpp"
#include "common/contact/two_bodies.hpp"

namespace chapter09 {

// The rows [first, last) of this rank, a whole number of nodes.
struct Ownership {
  PetscInt first = 0, last = 0, size = 0;  // size: all dofs
  bool owns(PetscInt dof) const { return dof >= first && dof < last; }
  PetscInt local() const { return last - first; }
};

// Cell rows [row0, row1) of each body, as a TwoBodies numbered on its own, with the map of
// its dofs to the global ones.
struct Part {
  mortar::TwoBodies bodies;
  std::array<std::pair<int, int>, 2> cell_rows;
  std::array<PetscInt, 2> first_dof;  // the global dof of each band's dof 0
  PetscInt global(int local_dof) const {
    const int l = local_dof < bodies.offset(1) ? 0 : 1;
    return first_dof[l] + (local_dof - bodies.offset(l));
  }
};

class RowSplit {
 public:
  RowSplit(const mortar::TwoBodyGeometry& g, int ranks);
  PetscInt num_dofs() const { return 2 * first_node(rows_[0] + rows_[1]); }
  int ranks() const { return static_cast<int>(first_row_.size()) - 1; }
  const mortar::TwoBodyGeometry& geometry() const { return g_; }
  // The global number of node (i, j) of body l (0 upper, 1 lower): column i, node row j from
  // the body's bottom. Its dofs are 2 node and 2 node + 1.
  PetscInt node(int l, int i, int j) const {
    const PetscInt body1 = static_cast<PetscInt>(rows_[0] + 1) * (columns_[0] + 1);
    return (l == 0 ? 0 : body1) + static_cast<PetscInt>(j) * (columns_[l] + 1) + i;
  }
  Ownership ownership(int rank) const;
  // rank's cell rows of both bodies, or the two rows along Gamma_c
  Part part(int rank, const mortar::Material& body1, const mortar::Material& body2) const;
  Part contact_strip(const mortar::Material& body1, const mortar::Material& body2) const;

 private:
  // k counts the cell rows of both bodies in order (body 1's, then body 2's); its first node
  PetscInt first_node(int k) const;
  Part make_part(std::array<std::pair<int, int>, 2> cell_rows, const mortar::Material& body1,
                 const mortar::Material& body2) const;
  mortar::TwoBodyGeometry g_;
  std::array<int, 2> columns_, rows_;  // cells across and up each body
  std::vector<int> first_row_;         // rank r: cell rows [first_row_[r], first_row_[r + 1])
};

}  // namespace chapter09
