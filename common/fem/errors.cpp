#include "common/fem/errors.hpp"

#include <cmath>
#include <stdexcept>

#include "common/fem/p2_elasticity.hpp"
#include "common/fem/quadrature.hpp"

namespace mortar {

SquaredNorms& SquaredNorms::operator+=(const SquaredNorms& o) {
  l2 += o.l2;
  h1_semi += o.h1_semi;
  energy += o.energy;
  return *this;
}

ErrorNorms& ErrorNorms::operator+=(const ErrorNorms& o) {
  error += o.error;
  exact += o.exact;
  return *this;
}

double ErrorNorms::relative_l2() const { return std::sqrt(error.l2 / exact.l2); }
double ErrorNorms::relative_h1_semi() const { return std::sqrt(error.h1_semi / exact.h1_semi); }
double ErrorNorms::relative_energy() const { return std::sqrt(error.energy / exact.energy); }

namespace {
// sigma(e) : eps(e) for a displacement gradient G (plane strain, isotropic).
double energy_density(const Eigen::Matrix2d& G, const Material& m) {
  const Eigen::Matrix2d eps = 0.5 * (G + G.transpose());
  const double tr = eps.trace();
  return m.lambda() * tr * tr + 2 * m.mu() * eps.squaredNorm();
}

// Adds the contributions of one quadrature point, of weight w, to the squared norms.
void add_point(ErrorNorms& out, double w, const Eigen::Vector2d& u, const Eigen::Vector2d& uh,
               const Eigen::Matrix2d& G, const Eigen::Matrix2d& grad_h, const Material& material) {
  out.error.l2 += w * (u - uh).squaredNorm();
  out.error.h1_semi += w * (G - grad_h).squaredNorm();
  out.error.energy += w * energy_density(G - grad_h, material);
  out.exact.l2 += w * u.squaredNorm();
  out.exact.h1_semi += w * G.squaredNorm();
  out.exact.energy += w * energy_density(G, material);
}

// The P2 case: u_h is quadratic and grad u_h linear on each triangle, so both are evaluated
// at every quadrature point, from the shape functions and the rows of the P2 strain matrix.
ErrorNorms p2_error_norms(const Mesh& mesh, const Material& material, const Eigen::VectorXd& u_h,
                          const ExactSolution& exact, int degree) {
  const TriangleRule rule = triangle_rule(degree);
  ErrorNorms out;
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    const auto x = triangle_vertices(mesh, t);
    const double area = mesh.area(t);
    const Eigen::Matrix<double, 12, 1> ue = p2_element_dofs(mesh, u_h, t);
    const BarycentricGradients gradients = barycentric_gradients(x);
    for (std::size_t q = 0; q < rule.points.size(); ++q) {
      const double s = rule.points[q].x(), r = rule.points[q].y();
      const Eigen::Vector3d lambda(1 - s - r, s, r);
      const Eigen::Matrix<double, 6, 1> N = p2_shape_values(lambda);
      const P2StrainMatrix B = p2_strain_matrix(gradients, lambda);
      Eigen::Vector2d uh = Eigen::Vector2d::Zero();
      Eigen::Matrix2d grad_h = Eigen::Matrix2d::Zero();
      for (int a = 0; a < 6; ++a) {
        uh += N[a] * ue.segment<2>(2 * a);
        grad_h += ue.segment<2>(2 * a) * Eigen::RowVector2d(B(0, 2 * a), B(1, 2 * a + 1));  // grad N_a
      }
      const Eigen::Vector2d p = x[0] + s * (x[1] - x[0]) + r * (x[2] - x[0]);
      add_point(out, area * rule.weights[q], exact.u(p), uh, exact.grad_u(p), grad_h, material);
    }
  }
  return out;
}
}  // namespace

ErrorNorms error_norms(const Mesh& mesh, const Material& material, const Eigen::VectorXd& u_h,
                       const ExactSolution& exact, int degree) {
  if (u_h.size() != mesh.num_dofs())
    throw std::invalid_argument("error_norms: u_h has " + std::to_string(u_h.size()) +
                                " entries, mesh has " + std::to_string(mesh.num_dofs()) + " dofs");
  if (mesh.degree() == 2) return p2_error_norms(mesh, material, u_h, exact, degree);
  const TriangleRule rule = triangle_rule(degree);
  ErrorNorms out;
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    const auto x = triangle_vertices(mesh, t);
    const auto& tri = mesh.triangles[t];
    const double area = mesh.area(t);
    const StrainMatrix B = strain_matrix(x);
    // grad u_h is constant on the triangle: rebuild it from the strain matrix rows
    Eigen::Matrix2d grad_h = Eigen::Matrix2d::Zero();
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d g(B(0, 2 * k), B(1, 2 * k + 1));  // grad of the hat of vertex k
      grad_h += u_h.segment<2>(2 * tri[k]) * g.transpose();
    }
    for (size_t q = 0; q < rule.points.size(); ++q) {
      const double s = rule.points[q].x(), r = rule.points[q].y();
      const Eigen::Vector2d p = x[0] + s * (x[1] - x[0]) + r * (x[2] - x[0]);
      const Eigen::Vector2d uh = (1 - s - r) * u_h.segment<2>(2 * tri[0]) +
                                 s * u_h.segment<2>(2 * tri[1]) + r * u_h.segment<2>(2 * tri[2]);
      const Eigen::Vector2d u = exact.u(p);
      const Eigen::Matrix2d G = exact.grad_u(p);
      add_point(out, area * rule.weights[q], u, uh, G, grad_h, material);
    }
  }
  return out;
}

}  // namespace mortar
