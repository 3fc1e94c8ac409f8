#include "common/fem/p1_elasticity.hpp"

#include "common/fem/p2_elasticity.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace mortar {

Material::Material(double E, double nu) : E_(E), nu_(nu) {
  if (!(std::isfinite(E) && E > 0))
    throw std::invalid_argument("Material: Young's modulus E must be > 0, got " + std::to_string(E));
  if (!(std::isfinite(nu) && nu > -1 && nu < 0.5))
    throw std::invalid_argument("Material: Poisson ratio nu must be in (-1, 0.5), got " +
                                std::to_string(nu));
}

Eigen::Matrix3d Material::voigt() const {
  const double l = lambda(), m = mu();
  Eigen::Matrix3d C;
  C << l + 2 * m, l, 0,
       l, l + 2 * m, 0,
       0, 0, m;
  return C;
}

std::array<Eigen::Vector2d, 3> triangle_vertices(const Mesh& mesh, int t) {
  const auto& tri = mesh.triangles[t];
  return {mesh.nodes[tri[0]], mesh.nodes[tri[1]], mesh.nodes[tri[2]]};
}

StrainMatrix strain_matrix(const std::array<Eigen::Vector2d, 3>& x) {
  const double twice_area =
      (x[1] - x[0]).x() * (x[2] - x[0]).y() - (x[1] - x[0]).y() * (x[2] - x[0]).x();
  if (!(twice_area > 0))
    throw std::invalid_argument("strain_matrix: triangle with non-positive area " +
                                std::to_string(0.5 * twice_area) + " at (" +
                                std::to_string(x[0].x()) + ", " + std::to_string(x[0].y()) + ")");
  StrainMatrix B = StrainMatrix::Zero();
  for (int k = 0; k < 3; ++k) {
    // grad of the barycentric coordinate of vertex k: the opposite edge turned by 90 degrees
    const Eigen::Vector2d& p = x[(k + 1) % 3];
    const Eigen::Vector2d& q = x[(k + 2) % 3];
    const double gx = (p.y() - q.y()) / twice_area, gy = (q.x() - p.x()) / twice_area;
    B(0, 2 * k) = gx;
    B(1, 2 * k + 1) = gy;
    B(2, 2 * k) = gy;
    B(2, 2 * k + 1) = gx;
  }
  return B;
}

ElementMatrix element_stiffness(const std::array<Eigen::Vector2d, 3>& x, const Material& material) {
  const StrainMatrix B = strain_matrix(x);
  const double area =
      0.5 * ((x[1] - x[0]).x() * (x[2] - x[0]).y() - (x[1] - x[0]).y() * (x[2] - x[0]).x());
  return area * B.transpose() * material.voigt() * B;
}

void add_stiffness_triplets(const Mesh& mesh, const Material& material, int offset,
                            std::vector<Eigen::Triplet<double>>& triplets) {
  if (mesh.degree() == 2) return add_p2_stiffness_triplets(mesh, material, offset, triplets);
  triplets.reserve(triplets.size() + 36 * mesh.triangles.size());
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    const ElementMatrix Ke = element_stiffness(triangle_vertices(mesh, t), material);
    const auto& tri = mesh.triangles[t];
    for (int a = 0; a < 6; ++a)
      for (int b = 0; b < 6; ++b)
        triplets.emplace_back(offset + 2 * tri[a / 2] + a % 2, offset + 2 * tri[b / 2] + b % 2, Ke(a, b));
  }
}

SparseMatrix assemble_stiffness(const Mesh& mesh, const Material& material) {
  std::vector<Eigen::Triplet<double>> triplets;
  add_stiffness_triplets(mesh, material, 0, triplets);
  SparseMatrix K(mesh.num_dofs(), mesh.num_dofs());
  K.setFromTriplets(triplets.begin(), triplets.end());  // duplicates are summed
  return K;
}

Eigen::VectorXd body_force_vector(const Mesh& mesh, const VectorField& f, int degree) {
  if (mesh.degree() == 2) return p2_body_force_vector(mesh, f, degree);
  const TriangleRule rule = triangle_rule(degree);
  Eigen::VectorXd F = Eigen::VectorXd::Zero(mesh.num_dofs());
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    const auto x = triangle_vertices(mesh, t);
    const double area = mesh.area(t);
    const auto& tri = mesh.triangles[t];
    for (size_t q = 0; q < rule.points.size(); ++q) {
      const double s = rule.points[q].x(), r = rule.points[q].y();
      const double phi[3] = {1 - s - r, s, r};
      const Eigen::Vector2d fq = f(x[0] + s * (x[1] - x[0]) + r * (x[2] - x[0]));
      for (int k = 0; k < 3; ++k) {
        F[2 * tri[k]] += area * rule.weights[q] * fq.x() * phi[k];
        F[2 * tri[k] + 1] += area * rule.weights[q] * fq.y() * phi[k];
      }
    }
  }
  return F;
}

namespace {
using Polygon = std::vector<Eigen::Vector2d>;

// The part of a convex polygon with x <= b (keep_left) or x >= b, by clipping against the line.
Polygon clip(const Polygon& poly, double b, bool keep_left) {
  Polygon out;
  const auto inside = [&](const Eigen::Vector2d& p) { return keep_left ? p.x() <= b : p.x() >= b; };
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const Eigen::Vector2d& a = poly[k];
    const Eigen::Vector2d& c = poly[(k + 1) % poly.size()];
    if (inside(a)) out.push_back(a);
    if (inside(a) != inside(c)) {
      const double t = (b - a.x()) / (c.x() - a.x());
      out.push_back(a + t * (c - a));
    }
  }
  return out;
}
}  // namespace

Eigen::VectorXd body_force_vector(const Mesh& mesh, const VectorField& f, int degree,
                                  const std::vector<double>& x_breaks) {
  if (x_breaks.empty()) return body_force_vector(mesh, f, degree);
  if (mesh.degree() == 2) throw std::invalid_argument("body_force_vector: breaks are for P1 meshes");
  const TriangleRule rule = triangle_rule(degree);
  Eigen::VectorXd F = Eigen::VectorXd::Zero(mesh.num_dofs());
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    const auto x = triangle_vertices(mesh, t);
    const auto& tri = mesh.triangles[t];
    // barycentric coordinates of the parent triangle: phi_k at any point of a piece
    Eigen::Matrix2d J;
    J << x[1] - x[0], x[2] - x[0];
    const Eigen::Matrix2d J_inv = J.inverse();
    std::vector<Polygon> pieces{{x[0], x[1], x[2]}};
    for (double b : x_breaks) {
      std::vector<Polygon> next;
      for (const Polygon& poly : pieces)
        for (bool left : {true, false}) {
          Polygon part = clip(poly, b, left);
          if (part.size() >= 3) next.push_back(std::move(part));
        }
      pieces = std::move(next);
    }
    for (const Polygon& poly : pieces)
      for (std::size_t k = 1; k + 1 < poly.size(); ++k) {  // fan of triangles
        const Eigen::Vector2d a = poly[0], e1 = poly[k] - a, e2 = poly[k + 1] - a;
        const double area = 0.5 * std::fabs(e1.x() * e2.y() - e1.y() * e2.x());
        if (!(area > 0)) continue;
        for (std::size_t q = 0; q < rule.points.size(); ++q) {
          const Eigen::Vector2d p = a + rule.points[q].x() * e1 + rule.points[q].y() * e2;
          const Eigen::Vector2d sr = J_inv * (p - x[0]);
          const double phi[3] = {1 - sr.x() - sr.y(), sr.x(), sr.y()};
          const Eigen::Vector2d fq = f(p);
          for (int c = 0; c < 3; ++c) {
            F[2 * tri[c]] += area * rule.weights[q] * fq.x() * phi[c];
            F[2 * tri[c] + 1] += area * rule.weights[q] * fq.y() * phi[c];
          }
        }
      }
  }
  return F;
}

void add_traction(Eigen::VectorXd& F, const Mesh& mesh, Side side, const VectorField& g,
                  int n_gauss) {
  if (mesh.degree() == 2) return add_p2_traction(F, mesh, side, g, n_gauss);
  const SegmentRule rule = gauss_legendre(n_gauss);
  const auto& nodes = mesh.nodes_on(side);
  for (size_t e = 0; e + 1 < nodes.size(); ++e) {
    const int a = nodes[e], b = nodes[e + 1];
    const Eigen::Vector2d xa = mesh.nodes[a], xb = mesh.nodes[b];
    const double length = (xb - xa).norm();
    for (size_t q = 0; q < rule.points.size(); ++q) {
      const double s = rule.points[q];
      const Eigen::Vector2d gq = length * rule.weights[q] * g(xa + s * (xb - xa));
      F.segment<2>(2 * a) += (1 - s) * gq;
      F.segment<2>(2 * b) += s * gq;
    }
  }
}

std::vector<Eigen::Vector3d> element_stresses(const Mesh& mesh, const Material& material,
                                              const Eigen::VectorXd& u) {
  if (mesh.degree() == 2) return p2_element_stresses(mesh, material, u);
  std::vector<Eigen::Vector3d> stress(mesh.triangles.size());
  const Eigen::Matrix3d C = material.voigt();
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    const auto& tri = mesh.triangles[t];
    Eigen::Matrix<double, 6, 1> ue;
    for (int k = 0; k < 3; ++k) ue.segment<2>(2 * k) = u.segment<2>(2 * tri[k]);
    stress[t] = C * strain_matrix(triangle_vertices(mesh, t)) * ue;
  }
  return stress;
}

}  // namespace mortar
