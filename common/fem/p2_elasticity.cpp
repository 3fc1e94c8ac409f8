#include "common/fem/p2_elasticity.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

#include "common/fem/lagrange_1d.hpp"

namespace mortar {

BarycentricGradients barycentric_gradients(const std::array<Eigen::Vector2d, 3>& x) {
  // read off the P1 strain matrix (it checks the orientation of the triangle)
  const StrainMatrix B1 = strain_matrix(x);
  BarycentricGradients out;
  for (int k = 0; k < 3; ++k) out.g[k] = Eigen::Vector2d(B1(0, 2 * k), B1(1, 2 * k + 1));
  return out;
}

P2StrainMatrix p2_strain_matrix(const std::array<Eigen::Vector2d, 3>& x, const Eigen::Vector3d& lambda) {
  return p2_strain_matrix(barycentric_gradients(x), lambda);
}

P2StrainMatrix p2_strain_matrix(const BarycentricGradients& gradients, const Eigen::Vector3d& lambda) {
  const std::array<Eigen::Vector2d, 3>& g = gradients.g;
  std::array<Eigen::Vector2d, 6> grad;
  for (int k = 0; k < 3; ++k) {
    const int l = (k + 1) % 3;
    grad[k] = (4 * lambda[k] - 1) * g[k];
    grad[3 + k] = 4 * (lambda[k] * g[l] + lambda[l] * g[k]);
  }
  P2StrainMatrix B = P2StrainMatrix::Zero();
  for (int a = 0; a < 6; ++a) {
    B(0, 2 * a) = grad[a].x();
    B(1, 2 * a + 1) = grad[a].y();
    B(2, 2 * a) = grad[a].y();
    B(2, 2 * a + 1) = grad[a].x();
  }
  return B;
}

Eigen::Matrix<double, 6, 1> p2_shape_values(const Eigen::Vector3d& l) {
  Eigen::Matrix<double, 6, 1> N;
  for (int k = 0; k < 3; ++k) {
    N[k] = l[k] * (2 * l[k] - 1);
    N[3 + k] = 4 * l[k] * l[(k + 1) % 3];
  }
  return N;
}

P2ElementMatrix p2_element_stiffness(const std::array<Eigen::Vector2d, 3>& x, const Material& material) {
  static const TriangleRule rule = triangle_rule(p2_stiffness_degree);
  return p2_element_stiffness(x, material, rule);
}

P2ElementMatrix p2_element_stiffness(const std::array<Eigen::Vector2d, 3>& x, const Material& material,
                                     const TriangleRule& rule) {
  const double area = 0.5 * ((x[1] - x[0]).x() * (x[2] - x[0]).y() - (x[1] - x[0]).y() * (x[2] - x[0]).x());
  const Eigen::Matrix3d C = material.voigt();
  const BarycentricGradients gradients = barycentric_gradients(x);
  P2ElementMatrix K = P2ElementMatrix::Zero();
  for (std::size_t q = 0; q < rule.points.size(); ++q) {
    const double s = rule.points[q].x(), t = rule.points[q].y();
    const P2StrainMatrix B = p2_strain_matrix(gradients, Eigen::Vector3d(1 - s - t, s, t));
    K += (area * rule.weights[q]) * B.transpose() * C * B;
  }
  return K;
}

}  // namespace mortar

namespace mortar {

std::array<int, 6> p2_element_nodes(const Mesh& mesh, int t) {
  const auto& v = mesh.triangles[t];
  const auto& m = mesh.edge_nodes[t];
  return {v[0], v[1], v[2], m[0], m[1], m[2]};
}

Mesh p2_mesh(const Mesh& p1) {
  if (p1.degree() != 1) throw std::invalid_argument("p2_mesh: the mesh is already P2");
  Mesh m;
  m.nodes = p1.nodes;
  m.triangles = p1.triangles;
  // one midpoint per edge, shared by the two triangles of an interior edge
  std::map<std::pair<int, int>, int> midpoint;
  const auto node_between = [&](int a, int b) {
    const std::pair<int, int> key = std::minmax(a, b);
    const auto [it, added] = midpoint.try_emplace(key, m.num_nodes());
    if (added) m.nodes.push_back(0.5 * (p1.nodes[a] + p1.nodes[b]));
    return it->second;
  };
  for (const auto& t : p1.triangles)
    m.edge_nodes.push_back({node_between(t[0], t[1]), node_between(t[1], t[2]), node_between(t[2], t[0])});
  // each side: its vertices in order, with the midpoint of each consecutive pair between them
  for (int side = 0; side < 4; ++side) {
    const std::vector<int>& v = p1.side_nodes[side];
    for (std::size_t k = 0; k < v.size(); ++k) {
      if (k > 0) {
        const auto it = midpoint.find(std::minmax(v[k - 1], v[k]));
        if (it == midpoint.end())
          throw std::logic_error("p2_mesh: side nodes " + std::to_string(v[k - 1]) + " and " + std::to_string(v[k]) +
                                 " share no triangle edge");
        m.side_nodes[side].push_back(it->second);
      }
      m.side_nodes[side].push_back(v[k]);
    }
  }
  return m;
}

void add_p2_stiffness_triplets(const Mesh& mesh, const Material& material, int offset,
                               std::vector<Eigen::Triplet<double>>& triplets) {
  triplets.reserve(triplets.size() + mesh.triangles.size() * 144);
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    const P2ElementMatrix K = p2_element_stiffness(triangle_vertices(mesh, t), material);
    const std::array<int, 6> e = p2_element_nodes(mesh, t);
    for (int a = 0; a < 6; ++a)
      for (int i = 0; i < 2; ++i)
        for (int b = 0; b < 6; ++b)
          for (int j = 0; j < 2; ++j)
            triplets.emplace_back(offset + 2 * e[a] + i, offset + 2 * e[b] + j, K(2 * a + i, 2 * b + j));
  }
}

Eigen::Matrix<double, 12, 1> p2_element_dofs(const Mesh& mesh, const Eigen::VectorXd& u, int t) {
  const std::array<int, 6> e = p2_element_nodes(mesh, t);
  Eigen::Matrix<double, 12, 1> ue;
  for (int a = 0; a < 6; ++a) ue.segment<2>(2 * a) = u.segment<2>(2 * e[a]);
  return ue;
}

Eigen::VectorXd p2_body_force_vector(const Mesh& mesh, const VectorField& f, int degree) {
  // N is one degree above the P1 hats and the rule is raised by two: f . N is exact for f a
  // polynomial of degree `degree` (on P1, of degree `degree` - 1)
  const TriangleRule rule = triangle_rule(degree + 2);
  Eigen::VectorXd F = Eigen::VectorXd::Zero(mesh.num_dofs());
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    const auto x = triangle_vertices(mesh, t);
    const double area = mesh.area(t);
    const std::array<int, 6> e = p2_element_nodes(mesh, t);
    for (std::size_t q = 0; q < rule.points.size(); ++q) {
      const double s = rule.points[q].x(), r = rule.points[q].y();
      const Eigen::Matrix<double, 6, 1> N = p2_shape_values(Eigen::Vector3d(1 - s - r, s, r));
      const Eigen::Vector2d fq = area * rule.weights[q] * f(x[0] + s * (x[1] - x[0]) + r * (x[2] - x[0]));
      for (int a = 0; a < 6; ++a) F.segment<2>(2 * e[a]) += N[a] * fq;
    }
  }
  return F;
}

void add_p2_traction(Eigen::VectorXd& F, const Mesh& mesh, Side side, const VectorField& g, int n_gauss) {
  // one point more than P1: the 1D shape functions are quadratic, not linear
  const SegmentRule rule = gauss_legendre(n_gauss + 1);
  const std::vector<int>& nodes = mesh.nodes_on(side);
  // the side's nodes run vertex, midpoint, vertex, ...: edge e is (nodes[2e], nodes[2e+1], nodes[2e+2])
  for (std::size_t e = 0; e + 2 < nodes.size(); e += 2) {
    const int a = nodes[e], m = nodes[e + 1], b = nodes[e + 2];
    const Eigen::Vector2d xa = mesh.nodes[a], xb = mesh.nodes[b];
    const double length = (xb - xa).norm();
    for (std::size_t q = 0; q < rule.points.size(); ++q) {
      const double s = rule.points[q];
      // the straight edge is affine in s, the midpoint at s = 1/2
      const Eigen::Vector2d gq = length * rule.weights[q] * g(xa + s * (xb - xa));
      const std::array<double, 3> phi = lagrange_1d(2, s);
      F.segment<2>(2 * a) += phi[0] * gq;
      F.segment<2>(2 * m) += phi[1] * gq;
      F.segment<2>(2 * b) += phi[2] * gq;
    }
  }
}

std::vector<Eigen::Vector3d> p2_element_stresses(const Mesh& mesh, const Material& material, const Eigen::VectorXd& u) {
  // the strain is linear in the triangle: one value per triangle is the one at its centroid
  const Eigen::Vector3d centroid = Eigen::Vector3d::Constant(1.0 / 3);
  const Eigen::Matrix3d C = material.voigt();
  std::vector<Eigen::Vector3d> stress(mesh.triangles.size());
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t)
    stress[t] = C * p2_strain_matrix(triangle_vertices(mesh, t), centroid) * p2_element_dofs(mesh, u, t);
  return stress;
}

}  // namespace mortar
