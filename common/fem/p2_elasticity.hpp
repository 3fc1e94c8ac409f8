// P2 (six-node) triangles for plane-strain elasticity (chapter 7 builds on them; paper: any
// degree q, here q = 2). Nodes 0, 1, 2 are the vertices, 3, 4, 5 the midpoints of the edges
// 0-1, 1-2, 2-0; the element is straight-sided, so the map from the reference triangle is
// affine. In barycentric coordinates lambda_k:
//     N_k = lambda_k (2 lambda_k - 1)  (vertices),     N_{3+k} = 4 lambda_k lambda_{k+1}  (midpoints),
// and unknowns are ordered as in P1, (u_x, u_y) node after node: dof 2a + c.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <vector>

#include "common/fem/mesh.hpp"
#include "common/fem/p1_elasticity.hpp"
#include "common/fem/quadrature.hpp"

namespace mortar {

using P2ElementMatrix = Eigen::Matrix<double, 12, 12>;
using P2StrainMatrix = Eigen::Matrix<double, 3, 12>;

// eps = B (u_x0, u_y0, ..., u_x5, u_y5) at the point with barycentric coordinates lambda: the
// gradients are grad N_k = (4 lambda_k - 1) grad lambda_k and
// grad N_{3+k} = 4 (lambda_k grad lambda_{k+1} + lambda_{k+1} grad lambda_k), linear in x,
// with grad lambda_k from the P1 strain matrix (constant on the triangle).
P2StrainMatrix p2_strain_matrix(const std::array<Eigen::Vector2d, 3>& vertices, const Eigen::Vector3d& lambda);

// grad lambda_k of a triangle, constant on it: computed once per triangle and given to the
// strain matrix at each quadrature point (the loops over triangles do that).
struct BarycentricGradients {
  std::array<Eigen::Vector2d, 3> g;
};
BarycentricGradients barycentric_gradients(const std::array<Eigen::Vector2d, 3>& vertices);
P2StrainMatrix p2_strain_matrix(const BarycentricGradients& gradients, const Eigen::Vector3d& lambda);

// The six shape functions N_0..N_5 at the point with barycentric coordinates lambda.
Eigen::Matrix<double, 6, 1> p2_shape_values(const Eigen::Vector3d& lambda);

// B is linear, so B^T C B is a quadratic: a triangle rule of degree 2 integrates K_T exactly.
constexpr int p2_stiffness_degree = 2;

// K_T = int_T B^T C B, by the triangle rule of degree p2_stiffness_degree unless another is given.
P2ElementMatrix p2_element_stiffness(const std::array<Eigen::Vector2d, 3>& vertices, const Material& material);
P2ElementMatrix p2_element_stiffness(const std::array<Eigen::Vector2d, 3>& vertices, const Material& material,
                                     const TriangleRule& rule);

}  // namespace mortar

namespace mortar {

// The P2 mesh of a P1 mesh (mesh.hpp): a node added at the midpoint of every edge. The
// vertices keep their P1 numbers, the midpoints follow them; each side's nodes, vertices and
// midpoints, stay ordered along the side (so a trace on Gamma_c has 2N + 1 nodes).
Mesh p2_mesh(const Mesh& p1);

// The six nodes of triangle t of a P2 mesh: vertices 0-2, then the midpoints of 0-1, 1-2, 2-0.
std::array<int, 6> p2_element_nodes(const Mesh& mesh, int t);

// The triplets of the P2 K of one body (12 x 12 element matrices), every dof shifted by
// offset; add_stiffness_triplets (p1_elasticity.hpp) calls it for a P2 mesh.
void add_p2_stiffness_triplets(const Mesh& mesh, const Material& material, int offset,
                               std::vector<Eigen::Triplet<double>>& triplets);

// The 12 unknowns of triangle t of a P2 mesh read out of a global field u, in element order.
Eigen::Matrix<double, 12, 1> p2_element_dofs(const Mesh& mesh, const Eigen::VectorXd& u, int t);

// The P2 versions of body_force_vector, add_traction and element_stresses (p1_elasticity.hpp),
// which call them for a P2 mesh; the rules they use are stated there.
Eigen::VectorXd p2_body_force_vector(const Mesh& mesh, const VectorField& f, int degree);
void add_p2_traction(Eigen::VectorXd& F, const Mesh& mesh, Side side, const VectorField& g, int n_gauss);
std::vector<Eigen::Vector3d> p2_element_stresses(const Mesh& mesh, const Material& material, const Eigen::VectorXd& u);

}  // namespace mortar
