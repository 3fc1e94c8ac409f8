#include "common/interface/dual_basis.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/fem/quadrature.hpp"
#include "common/timing/profile.hpp"

namespace mortar {

Eigen::Matrix2d dual_element_coefficients(double h) {
  Eigen::Matrix2d mass;  // int_e phi_a phi_b
  mass << h / 3, h / 6, h / 6, h / 3;
  const Eigen::Matrix2d lumped = (Eigen::Vector2d() << h / 2, h / 2).finished().asDiagonal();
  // psi = A phi with A M = D_e: then int psi_a phi_b = (A M)_ab = (D_e)_ab.
  return lumped * mass.inverse();
}

MultiplierSpace dual_end_modified_p1(const InterfaceTrace& t) {
  const ProfilePhase phase("interface and constraints");
  const int N = t.num_elements();
  if (N < 2)
    throw std::invalid_argument("dual_end_modified_p1: the non-mortar trace needs at least 2 elements, it has " +
                                std::to_string(N));
  MultiplierSpace space = end_modified_p1(t);  // C: the hats on the same nodes
  std::vector<Eigen::Triplet<double>> entries;
  // End elements: psi_1 = 1 on element 0 and psi_{N-1} = 1 on element N - 1 (both local hats).
  for (int l = 0; l < 2; ++l) {
    entries.emplace_back(0, l, 1.0);
    entries.emplace_back(N - 2, 2 * (N - 1) + l, 1.0);
  }
  // Interior elements e = 1 .. N-2, nodes e and e + 1, carrying psi_{e-1} and psi_e (the
  // multiplier of node j is psi_{j-1}).
  for (int e = 1; e + 1 < N; ++e) {
    const Eigen::Matrix2d A = dual_element_coefficients(t.x[e + 1] - t.x[e]);
    for (int a = 0; a < 2; ++a)
      for (int l = 0; l < 2; ++l) entries.emplace_back(e - 1 + a, 2 * e + l, A(a, l));
  }
  space.E.resize(N - 1, 2 * N);
  space.E.setFromTriplets(entries.begin(), entries.end());
  return space;
}

double d_offdiagonal_max(const MultiplierSpace& space, const Eigen::SparseMatrix<double, Eigen::RowMajor>& D) {
  std::vector<int> multiplier_at(static_cast<std::size_t>(D.cols()), -1);
  for (int i = 0; i < space.dim(); ++i) multiplier_at[space.node_of(i)] = i;
  double worst = 0;
  for (int i = 0; i < D.rows(); ++i) {
    const double diagonal = D.coeff(i, space.node_of(i));
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(D, i); it; ++it)
      if (multiplier_at[it.col()] >= 0 && multiplier_at[it.col()] != i)
        worst = std::max(worst, std::fabs(it.value()) / std::fabs(diagonal));
  }
  return worst;
}

BrokenCurve multiplier_function(const MultiplierSpace& space, const InterfaceTrace& t,
                                const Eigen::VectorXd& coefficients) {
  if (space.degree != 1)
    throw std::invalid_argument("multiplier_function: a broken curve is P1, the space is P" +
                                std::to_string(space.degree));
  const Eigen::VectorXd local = space.element_coefficients().transpose() * coefficients;
  BrokenCurve curve{t.x, {}, {}};
  for (int e = 0; e < t.num_elements(); ++e) {
    curve.left.push_back(local[2 * e]);
    curve.right.push_back(local[2 * e + 1]);
  }
  return curve;
}

double l2_error(const BrokenCurve& lambda_h, const std::function<double(double)>& p) {
  // 4 pieces per element, 5 Gauss points each: p may have a kink inside an element.
  static const SegmentRule rule = gauss_legendre(5);
  constexpr int pieces = 4;
  // the differences first, then their squares divided by the largest: pressures of 1e300 Pa
  // would overflow when squared (the relative error means the same in any unit of stress)
  std::vector<double> d, weight;
  for (std::size_t e = 0; e + 1 < lambda_h.x.size(); ++e) {
    const double a = lambda_h.x[e], h = lambda_h.x[e + 1] - a;
    for (int piece = 0; piece < pieces; ++piece)
      for (std::size_t q = 0; q < rule.points.size(); ++q) {
        const double s = (piece + rule.points[q]) / pieces;
        d.push_back(lambda_h(static_cast<int>(e), s) - p(a + s * h));
        weight.push_back(rule.weights[q] * h / pieces);
      }
  }
  double scale = 0;
  for (double v : d) scale = std::max(scale, std::fabs(v));
  if (!(scale > 0)) return 0.0;
  double sum = 0;
  for (std::size_t k = 0; k < d.size(); ++k) sum += weight[k] * (d[k] / scale) * (d[k] / scale);
  return scale * std::sqrt(sum);
}

}  // namespace mortar
