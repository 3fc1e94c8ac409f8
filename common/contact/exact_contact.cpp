#include "common/contact/exact_contact.hpp"

#include "common/fem/quadrature.hpp"

namespace mortar {

double ExactContact::total_force(double L) const {
  const SegmentRule g = gauss_legendre(8);
  const int pieces = 64;
  double total = 0;
  for (int e = 0; e < pieces; ++e)
    for (std::size_t q = 0; q < g.points.size(); ++q)
      total += g.weights[q] * L / pieces * pressure(L * (e + g.points[q]) / pieces);
  return total;
}

double ExactContact::normal_jump(double x) const {
  const Eigen::Vector2d on_gamma(x, 0.0);
  return u(1, on_gamma).y() - u(0, on_gamma).y();
}

Eigen::Matrix2d ExactContact::stress(int l, const Eigen::Vector2d& p) const {
  const Eigen::Matrix2d G = grad_u(l, p);
  const Eigen::Matrix2d eps = 0.5 * (G + G.transpose());
  const Material& m = material(l);
  return m.lambda() * eps.trace() * Eigen::Matrix2d::Identity() + 2 * m.mu() * eps;
}

ExactSolution ExactContact::exact(int l) const {
  return {[this, l](const Eigen::Vector2d& p) { return u(l, p); },
          [this, l](const Eigen::Vector2d& p) { return grad_u(l, p); }};
}

}  // namespace mortar
