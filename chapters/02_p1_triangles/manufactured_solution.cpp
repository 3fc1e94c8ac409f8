#include "manufactured_solution.hpp"

#include <cmath>

namespace chapter02 {

namespace {
constexpr double pi = 3.14159265358979323846;
}

ManufacturedSolution::ManufacturedSolution(const mortar::Material& material, double amplitude)
    : material_(material), A_(amplitude) {}

Eigen::Vector2d ManufacturedSolution::u(const Eigen::Vector2d& p) const {
  const double x = p.x(), y = p.y();
  return {A_ * std::sin(pi * x) * std::cos(pi * y), A_ * std::exp(x) * std::sin(pi * y)};
}

Eigen::Matrix2d ManufacturedSolution::grad_u(const Eigen::Vector2d& p) const {
  const double x = p.x(), y = p.y();
  Eigen::Matrix2d G;
  G << A_ * pi * std::cos(pi * x) * std::cos(pi * y), -A_ * pi * std::sin(pi * x) * std::sin(pi * y),
       A_ * std::exp(x) * std::sin(pi * y), A_ * pi * std::exp(x) * std::cos(pi * y);
  return G;
}

Eigen::Matrix2d ManufacturedSolution::stress(const Eigen::Vector2d& p) const {
  const Eigen::Matrix2d G = grad_u(p);
  const Eigen::Matrix2d eps = 0.5 * (G + G.transpose());
  return material_.lambda() * eps.trace() * Eigen::Matrix2d::Identity() + 2 * material_.mu() * eps;
}

Eigen::Vector2d ManufacturedSolution::body_force(const Eigen::Vector2d& p) const {
  const double x = p.x(), y = p.y();
  const double sx = std::sin(pi * x), cx = std::cos(pi * x);
  const double sy = std::sin(pi * y), cy = std::cos(pi * y), ex = std::exp(x);
  // second derivatives of u_x and u_y
  const double ux_xx = -A_ * pi * pi * sx * cy, ux_xy = -A_ * pi * pi * cx * sy,
               ux_yy = -A_ * pi * pi * sx * cy;
  const double uy_xx = A_ * ex * sy, uy_xy = A_ * pi * ex * cy, uy_yy = -A_ * pi * pi * ex * sy;
  const double lambda = material_.lambda(), mu = material_.mu();
  const Eigen::Vector2d laplacian(ux_xx + ux_yy, uy_xx + uy_yy);
  const Eigen::Vector2d grad_div(ux_xx + uy_xy, ux_xy + uy_yy);
  return -(mu * laplacian + (lambda + mu) * grad_div);
}

Eigen::Vector2d ManufacturedSolution::traction(const Eigen::Vector2d& p,
                                               const Eigen::Vector2d& normal) const {
  return stress(p) * normal;
}

mortar::ExactSolution ManufacturedSolution::exact() const {
  return {[this](const Eigen::Vector2d& p) { return u(p); },
          [this](const Eigen::Vector2d& p) { return grad_u(p); }};
}

}  // namespace chapter02
