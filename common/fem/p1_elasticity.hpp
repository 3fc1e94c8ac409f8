// P1 plane-strain linear elasticity: material law, element matrix, assembly, loads, stresses.
//
// Unknowns are nodal displacements, two per node, ordered u = (u_x(a0), u_y(a0), u_x(a1), ...),
// so dof 2a + c is component c at node a. The bilinear form is a(u, v) = int sigma(u) : eps(v)
// with sigma = lambda tr(eps) I + 2 mu eps (paper eq. (2), isotropic A).
#pragma once

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <array>
#include <functional>

#include "common/fem/mesh.hpp"
#include "common/fem/quadrature.hpp"

namespace mortar {

using SparseMatrix = Eigen::SparseMatrix<double>;  // column-major, the layout solvers expect
using VectorField = std::function<Eigen::Vector2d(const Eigen::Vector2d&)>;

// Isotropic material in plane strain; the constructor rejects E <= 0 and nu outside (-1, 0.5).
class Material {
 public:
  Material(double E, double nu);
  double E() const { return E_; }
  double nu() const { return nu_; }
  double lambda() const { return E_ * nu_ / ((1 + nu_) * (1 - 2 * nu_)); }
  double mu() const { return E_ / (2 * (1 + nu_)); }
  // Voigt matrix C with sigma = C eps, eps = (eps_xx, eps_yy, 2 eps_xy).
  Eigen::Matrix3d voigt() const;

 private:
  double E_, nu_;
};

using ElementMatrix = Eigen::Matrix<double, 6, 6>;
using StrainMatrix = Eigen::Matrix<double, 3, 6>;

// eps = Bmat * (u_x0, u_y0, u_x1, u_y1, u_x2, u_y2) on a triangle; the P1 gradients are constant.
StrainMatrix strain_matrix(const std::array<Eigen::Vector2d, 3>& x);
// K_T = area * B^T C B, the 6 x 6 stiffness of one triangle.
ElementMatrix element_stiffness(const std::array<Eigen::Vector2d, 3>& x, const Material& material);

// Global stiffness K of one body, assembled from element matrices by triplets (P2 elements on
// a P2 mesh, common/fem/p2_elasticity.hpp).
SparseMatrix assemble_stiffness(const Mesh& mesh, const Material& material);
// The triplets of K, with every dof index shifted by `offset` (several bodies, one matrix).
void add_stiffness_triplets(const Mesh& mesh, const Material& material, int offset,
                            std::vector<Eigen::Triplet<double>>& triplets);

// Load vector of a body force f: F_i = int f . phi_i, with a triangle rule of the given degree;
// on a P2 mesh (the six shape functions, p2_elasticity.hpp) the rule's degree is degree + 2,
// as the shape functions are one degree higher: f . phi_i is exact for f of degree `degree`.
Eigen::VectorXd body_force_vector(const Mesh& mesh, const VectorField& f, int degree);
// The same for a force that jumps across the vertical lines x = b, b in x_breaks (P1 only): a
// triangle a line crosses is cut along it and each piece integrated by the rule, so the jump
// costs no accuracy (a rule across it would make an O(h^2) error in every cut triangle: a
// line load of O(h), which caps the L2 rate at 1).
Eigen::VectorXd body_force_vector(const Mesh& mesh, const VectorField& f, int degree, const std::vector<double>& x_breaks);
// Adds the load of a traction g on one side: F_i += int_side g . phi_i (Gauss-Legendre, n points;
// n + 1 on a P2 mesh, whose side edges carry the quadratics (1-s)(1-2s), 4s(1-s), s(2s-1)).
void add_traction(Eigen::VectorXd& F, const Mesh& mesh, Side side, const VectorField& g, int n_gauss);

// Stress (sigma_xx, sigma_yy, sigma_xy) in each triangle for a nodal field u: constant on a P1
// mesh; on a P2 mesh it is linear in the triangle, and this is its value at the centroid.
std::vector<Eigen::Vector3d> element_stresses(const Mesh& mesh, const Material& material,
                                              const Eigen::VectorXd& u);

std::array<Eigen::Vector2d, 3> triangle_vertices(const Mesh& mesh, int t);

}  // namespace mortar
