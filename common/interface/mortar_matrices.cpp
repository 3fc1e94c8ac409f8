#include "common/interface/mortar_matrices.hpp"

#include <vector>

#include "common/study/profile.hpp"
#include "common/fem/quadrature.hpp"

namespace mortar {

MortarMatrices mortar_matrices(const InterfaceTrace& t1, const InterfaceTrace& t2,
                               const MergedGrid& grid, const MultiplierSpace& space) {
  const ProfilePhase phase("interface and constraints");
  // First the products of the local hats of each trace-1 element with the P1 hats on the
  // merged grid: mass_jl = int phi^{1,e}_j phi^1_l and mixed_jk = int phi^{1,e}_j phi^2_k, row
  // 2e + j for the local hat j of element e. Then D = E mass and M = E mixed, with psi_i = E phi^{1,e}
  // (multiplier_space.hpp): the same products serve continuous and discontinuous bases.
  const SegmentRule gauss = gauss_legendre(2);
  std::vector<Eigen::Triplet<double>> mass, mixed;
  for (const MergedSegment& seg : grid.segments) {
    const int e1 = seg.element1, e2 = seg.element2;
    // The segment's ends in each element's local coordinate, before any Gauss point: the
    // differences of nearby coordinates are exact (Sterbenz), whereas a Gauss point x ~ L
    // carries an error of eps L, which would cost eps L / h relative to h (the dual basis's
    // off-diagonal D_ij, 2 int phi_a phi_b - int phi_b^2 = 0, cancels to that size).
    const double h1 = t1.x[e1 + 1] - t1.x[e1], h2 = t2.x[e2 + 1] - t2.x[e2];
    const double a1 = (seg.a - t1.x[e1]) / h1, b1 = (seg.b - t1.x[e1]) / h1;
    const double a2 = (seg.a - t2.x[e2]) / h2, b2 = (seg.b - t2.x[e2]) / h2;
    for (std::size_t q = 0; q < gauss.points.size(); ++q) {
      const double w = gauss.weights[q] * (seg.b - seg.a);
      const double s1 = a1 + gauss.points[q] * (b1 - a1);
      const double s2 = a2 + gauss.points[q] * (b2 - a2);
      const double phi1[2] = {1 - s1, s1}, phi2[2] = {1 - s2, s2};
      for (int j = 0; j < 2; ++j) {
        for (int l = 0; l < 2; ++l) mass.emplace_back(2 * e1 + j, e1 + l, w * phi1[j] * phi1[l]);
        for (int k = 0; k < 2; ++k) mixed.emplace_back(2 * e1 + j, e2 + k, w * phi1[j] * phi2[k]);
      }
    }
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor> mass11(2 * t1.num_elements(), t1.num_nodes());
  Eigen::SparseMatrix<double, Eigen::RowMajor> mixed12(2 * t1.num_elements(), t2.num_nodes());
  mass11.setFromTriplets(mass.begin(), mass.end());
  mixed12.setFromTriplets(mixed.begin(), mixed.end());
  const RowMajorMatrix E = space.element_coefficients();

  MortarMatrices m;
  m.D = E * mass11;
  m.M = E * mixed12;
  return m;
}

}  // namespace mortar
