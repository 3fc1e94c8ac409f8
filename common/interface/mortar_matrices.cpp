#include "common/interface/mortar_matrices.hpp"

#include <vector>

#include "common/study/profile.hpp"
#include "common/fem/quadrature.hpp"

namespace mortar {

MortarMatrices mortar_matrices(const InterfaceTrace& t1, const InterfaceTrace& t2,
                               const MergedGrid& grid, const MultiplierSpace& space) {
  const ProfilePhase phase("interface and constraints");
  // First the P1 products on the merged grid: mass11_jl = int phi^1_j phi^1_l and
  // mixed12_jk = int phi^1_j phi^2_k; then D = C mass11 and M = C mixed12 (psi = C phi^1).
  const SegmentRule gauss = gauss_legendre(2);
  std::vector<Eigen::Triplet<double>> mass, mixed;
  for (const MergedSegment& seg : grid.segments) {
    const int e1 = seg.element1, e2 = seg.element2;
    for (std::size_t q = 0; q < gauss.points.size(); ++q) {
      const double x = seg.a + gauss.points[q] * (seg.b - seg.a);
      const double w = gauss.weights[q] * (seg.b - seg.a);
      const double s1 = (x - t1.x[e1]) / (t1.x[e1 + 1] - t1.x[e1]);
      const double s2 = (x - t2.x[e2]) / (t2.x[e2 + 1] - t2.x[e2]);
      const double phi1[2] = {1 - s1, s1}, phi2[2] = {1 - s2, s2};
      for (int j = 0; j < 2; ++j) {
        for (int l = 0; l < 2; ++l) mass.emplace_back(e1 + j, e1 + l, w * phi1[j] * phi1[l]);
        for (int k = 0; k < 2; ++k) mixed.emplace_back(e1 + j, e2 + k, w * phi1[j] * phi2[k]);
      }
    }
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor> mass11(t1.num_nodes(), t1.num_nodes());
  Eigen::SparseMatrix<double, Eigen::RowMajor> mixed12(t1.num_nodes(), t2.num_nodes());
  mass11.setFromTriplets(mass.begin(), mass.end());
  mixed12.setFromTriplets(mixed.begin(), mixed.end());

  MortarMatrices m;
  m.D = space.C * mass11;
  m.M = space.C * mixed12;
  return m;
}

}  // namespace mortar
