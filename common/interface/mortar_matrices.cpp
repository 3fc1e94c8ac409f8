#include "common/interface/mortar_matrices.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/fem/lagrange_1d.hpp"
#include "common/fem/quadrature.hpp"
#include "common/timing/profile.hpp"

namespace mortar {

int mortar_gauss_points(int degree1, int degree2) { return std::max(degree1, degree2) + 1; }

MortarMatrices mortar_matrices(const InterfaceTrace& t1, const InterfaceTrace& t2,
                               const MergedGrid& grid, const MultiplierSpace& space) {
  const ProfilePhase phase("interface and constraints");
  // First the products of the local functions of each trace-1 element with the trace functions
  // on the merged grid: mass_jl = int phi^{1,e}_j phi^1_l and mixed_jk = int phi^{1,e}_j phi^2_k,
  // row (q1 + 1) e + j for the local function j of element e. Then D = E mass and M = E mixed,
  // with psi_i = E phi^{1,e} (multiplier_space.hpp): the same products serve continuous and
  // discontinuous bases, P1 and P2.
  const int q1 = t1.degree, q2 = t2.degree, n1 = q1 + 1, n2 = q2 + 1;
  if (space.degree != q1)
    throw std::invalid_argument("mortar_matrices: M_h is of degree " + std::to_string(space.degree) +
                                ", trace 1 of degree " + std::to_string(q1));
  const SegmentRule gauss = gauss_legendre(mortar_gauss_points(q1, q2));
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
      const std::array<double, 3> phi1 = lagrange_1d(q1, s1), phi2 = lagrange_1d(q2, s2);
      for (int j = 0; j < n1; ++j) {
        for (int l = 0; l < n1; ++l) mass.emplace_back(n1 * e1 + j, q1 * e1 + l, w * phi1[j] * phi1[l]);
        for (int k = 0; k < n2; ++k) mixed.emplace_back(n1 * e1 + j, q2 * e2 + k, w * phi1[j] * phi2[k]);
      }
    }
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor> mass11(n1 * t1.num_elements(), t1.num_dofs());
  Eigen::SparseMatrix<double, Eigen::RowMajor> mixed12(n1 * t1.num_elements(), t2.num_dofs());
  mass11.setFromTriplets(mass.begin(), mass.end());
  mixed12.setFromTriplets(mixed.begin(), mixed.end());
  const RowMajorMatrix E = space.element_coefficients();

  MortarMatrices m;
  m.D = E * mass11;
  m.M = E * mixed12;
  return m;
}

}  // namespace mortar
