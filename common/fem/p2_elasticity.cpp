#include "common/fem/p2_elasticity.hpp"

#include <algorithm>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>

namespace mortar {

P2StrainMatrix p2_strain_matrix(const std::array<Eigen::Vector2d, 3>& x, const Eigen::Vector3d& lambda) {
  // grad lambda_k, read off the P1 strain matrix (it checks the orientation of the triangle)
  const StrainMatrix B1 = strain_matrix(x);
  std::array<Eigen::Vector2d, 3> g;
  for (int k = 0; k < 3; ++k) g[k] = Eigen::Vector2d(B1(0, 2 * k), B1(1, 2 * k + 1));
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

P2ElementMatrix p2_element_stiffness(const std::array<Eigen::Vector2d, 3>& x, const Material& material) {
  static const TriangleRule rule = triangle_rule(p2_stiffness_degree);
  return p2_element_stiffness(x, material, rule);
}

P2ElementMatrix p2_element_stiffness(const std::array<Eigen::Vector2d, 3>& x, const Material& material,
                                     const TriangleRule& rule) {
  const double area = 0.5 * ((x[1] - x[0]).x() * (x[2] - x[0]).y() - (x[1] - x[0]).y() * (x[2] - x[0]).x());
  const Eigen::Matrix3d C = material.voigt();
  P2ElementMatrix K = P2ElementMatrix::Zero();
  for (std::size_t q = 0; q < rule.points.size(); ++q) {
    const double s = rule.points[q].x(), t = rule.points[q].y();
    const P2StrainMatrix B = p2_strain_matrix(x, Eigen::Vector3d(1 - s - t, s, t));
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

}  // namespace mortar
