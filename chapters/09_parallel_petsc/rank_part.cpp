#include "rank_part.hpp"

#include <algorithm>

#include "common/fem/mesh.hpp"

namespace chapter09 {

RowSplit::RowSplit(const mortar::TwoBodyGeometry& g, int ranks)
    : g_(g), columns_{g.n1, g.n2}, rows_{g.m1, g.m2}, first_row_(static_cast<std::size_t>(ranks) + 1) {
  // rank r starts at the first cell row at or past r / ranks of the nodes
  const int rows = rows_[0] + rows_[1];
  const double nodes = static_cast<double>(first_node(rows));
  int k = 0;
  for (int r = 0; r <= ranks; ++r) {
    while (k < rows && static_cast<double>(first_node(k)) < nodes * r / ranks) ++k;
    first_row_[r] = k;
  }
  first_row_.back() = rows;
}

PetscInt RowSplit::first_node(int k) const {
  // a row of body l holds (n_l + 1) nodes; a body's top row goes with its last cell row
  const PetscInt across1 = columns_[0] + 1, across2 = columns_[1] + 1, body1 = (rows_[0] + 1) * across1;
  if (k < rows_[0]) return k * across1;
  if (k < rows_[0] + rows_[1]) return body1 + static_cast<PetscInt>(k - rows_[0]) * across2;
  return body1 + (rows_[1] + 1) * across2;
}

Ownership RowSplit::ownership(int rank) const {
  return {2 * first_node(first_row_[rank]), 2 * first_node(first_row_[rank + 1]), num_dofs()};
}

Part RowSplit::part(int rank, const mortar::Material& body1, const mortar::Material& body2) const {
  const int k0 = first_row_[rank], k1 = first_row_[rank + 1];
  const auto within = [](int k, int lo, int count) { return std::clamp(k - lo, 0, count); };
  return make_part({{{within(k0, 0, rows_[0]), within(k1, 0, rows_[0])},
                     {within(k0, rows_[0], rows_[1]), within(k1, rows_[0], rows_[1])}}},
                   body1, body2);
}

Part RowSplit::contact_strip(const mortar::Material& body1, const mortar::Material& body2) const {
  return make_part({{{0, 1}, {rows_[1] - 1, rows_[1]}}}, body1, body2);
}

Part RowSplit::make_part(std::array<std::pair<int, int>, 2> cell_rows, const mortar::Material& body1,
                         const mortar::Material& body2) const {
  const auto band = [&](int l) {
    return mortar::rectangle_band(mortar::body_rectangle(g_, l), cell_rows[l].first, cell_rows[l].second);
  };
  // band node 0 is node row0 (n_l + 1) of its body
  const PetscInt first1 = 2 * first_node(cell_rows[0].first);
  const PetscInt first2 = 2 * (first_node(rows_[0]) + static_cast<PetscInt>(cell_rows[1].first) * (columns_[1] + 1));
  return Part{mortar::TwoBodies({band(0), body1}, {band(1), body2}), cell_rows, {first1, first2}};
}

}  // namespace chapter09
