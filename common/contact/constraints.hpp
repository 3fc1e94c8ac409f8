// The discrete contact conditions on Gamma_c as rows of a matrix B acting on the global
// displacement vector of both bodies (paper section 3; README.md, "Notation"):
//  - pointwise matching (space V_h^P), one row per node a of the non-mortar trace:
//      (B u)_a = [u_h.n](a) = u_nm(a).n_nm + sum_k phi^m_k(a) u_m,k.n_m;
//  - integral matching (space V_h^I), one row per multiplier psi_i of M_h:
//      (B u)_i = int psi_i [u_h.n] = sum_j D_ij u_nm,j.n_nm + sum_k M_ik u_m,k.n_m.
// [u.n] = u1.n1 + u2.n2 = u2_y - u1_y, positive for penetration. Bilateral contact is B u = 0;
// unilateral contact (chapter 5) is B u <= G.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "common/interface/interface_trace.hpp"
#include "common/interface/merged_grid.hpp"
#include "common/interface/mortar_matrices.hpp"
#include "common/interface/multiplier_space.hpp"
#include "common/contact/two_bodies.hpp"

namespace mortar {

enum class Matching { pointwise, integral };
Matching parse_matching(const std::string& name);
std::string matching_name(Matching m);

// Everything the two matchings need to know about Gamma_c: which body is the non-mortar
// side, both traces, their merged grid, M_h on the non-mortar trace and D, M.
struct ContactInterface {
  int nonmortar = 0;  // body index: 0 = body 1 (the paper's default), 1 = body 2
  int mortar() const { return 1 - nonmortar; }
  InterfaceTrace nonmortar_trace, mortar_trace;
  MergedGrid grid;
  MultiplierSpace space;
  MortarMatrices matrices;
};

// Gamma_c seen from both sides: the bottom trace of body 1 and the top trace of body 2, the
// non-mortar one first. Grid, space and matrices are left empty.
ContactInterface contact_traces(const TwoBodies& bodies, int nonmortar);

// All of ContactInterface: the traces, their merged grid, M_h^1 (end-modified P1 on the
// non-mortar trace) and D, M on the merged grid. Chapter 4's level.cpp shows these steps.
ContactInterface make_interface(const TwoBodies& bodies, int nonmortar, double merge_tol = 1e-12);
// The same with the dual basis of chapter 6 (common/interface/dual_basis.hpp) in place of the
// hats of M_h^1: D diagonal.
ContactInterface make_dual_interface(const TwoBodies& bodies, int nonmortar);

// The coefficients of each row of B before the normals and the global dofs are attached:
// (B u)_row = sum_j nonmortar(row, j) u_nm,j.n_nm + sum_k mortar(row, k) u_m,k.n_m.
struct MatchingRows {
  Matching matching = Matching::integral;
  Eigen::SparseMatrix<double, Eigen::RowMajor> nonmortar, mortar;
  std::vector<int> row_node;  // the non-mortar trace node each row sits on
};
// Pointwise matching (V_h^P): one row per node a of xi^1, u^1(a).n^1 + u^2(a).n^2 with u^2(a)
// interpolated from the two mortar hats on the element containing x_a. Needs only the traces.
MatchingRows pointwise_matching_rows(const ContactInterface& gamma);
// Integral matching (V_h^I): the rows are D and M, one per multiplier psi_i of M_h^1
// (int psi_i [u_h.n] = sum_j D_ij u^1_j.n^1 + sum_k M_ik u^2_k.n^2). Needs gamma.matrices.
MatchingRows integral_matching_rows(const ContactInterface& gamma);
// The rows of the matching given by name (chapter 5 takes either).
MatchingRows matching_rows(const ContactInterface& gamma, Matching matching);

struct Constraints {
  Matching matching = Matching::integral;
  SparseMatrix B;              // rows x num_dofs of both bodies
  std::vector<int> row_node;   // non-mortar trace node each row sits on (a, or psi_i's node)
  std::vector<int> row_source;  // index of the row before dropping (node a, or i of psi_i)
  // The non-mortar normal dof of each row's node: the unknown a row can be solved for.
  std::vector<int> pivot_dof;
};

// B: the rows attached to the normal dofs of both bodies (n^1 = (0, -1), n^2 = (0, 1)). Rows
// whose every entry sits on a prescribed (Dirichlet) dof are dropped: such a row says nothing
// about the unknowns and would make the saddle-point matrix singular.
Constraints constraint_rows(const TwoBodies& bodies, const ContactInterface& gamma, const MatchingRows& rows,
                            const std::vector<bool>& prescribed);
// The same rows on the tangential dofs (chapter 8): (B_t u)_i = int psi_i [u_t] with the slip
// [u_t] = u^1_x - u^2_x of body 1 over body 2, pivots on the non-mortar x dofs.
Constraints tangential_constraint_rows(const TwoBodies& bodies, const ContactInterface& gamma,
                                       const MatchingRows& rows, const std::vector<bool>& prescribed);
// constraint_rows of the matching's own rows.
Constraints build_constraints(const TwoBodies& bodies, const ContactInterface& gamma,
                              Matching matching, const std::vector<bool>& prescribed);

// The right-hand side G of B u <= G for an initial gap g(x) >= 0 (paper section 5):
// G_a = g(a) for pointwise rows, G_i = int g psi_i for integral rows (3-point Gauss on each
// element of the non-mortar trace: exact for the quadratic gap of the Hertz scene).
Eigen::VectorXd tested_gap(const ContactInterface& gamma, const Constraints& c,
                           const std::function<double(double)>& g);

}  // namespace mortar
