// Dirichlet data by elimination: the prescribed dofs leave the system, their values move to
// the right-hand side. What remains, K_ff u_f = F_f - K_fd u_d, is symmetric positive definite
// as soon as the prescribed dofs stop every rigid-body motion.
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "common/fem/mesh.hpp"
#include "common/fem/p1_elasticity.hpp"

namespace mortar {

struct DirichletData {
  std::vector<int> dofs;       // prescribed dof indices (duplicates allowed, last value wins)
  std::vector<double> values;  // their values
};

// Prescribes u = g(x) at every node of the given sides (both components).
void prescribe_on_sides(DirichletData& data, const Mesh& mesh, const std::vector<Side>& sides,
                        const VectorField& g);

struct ReducedSystem {
  SparseMatrix K;               // K_ff
  Eigen::VectorXd rhs;          // F_f - K_fd u_d
  std::vector<int> free_dofs;   // free index -> full dof
  Eigen::VectorXd prescribed;   // full-length vector holding u_d (zero on free dofs)
  std::vector<int> full_to_free;  // full dof -> free index, -1 where prescribed

  // The full displacement vector from the free unknowns.
  Eigen::VectorXd expand(const Eigen::VectorXd& u_free) const;
};

// Builds K_ff column by column straight from K's compressed storage (no dense work).
ReducedSystem eliminate_dirichlet(const SparseMatrix& K, const Eigen::VectorXd& F,
                                  const DirichletData& data);
// New loads and prescribed values on the same prescribed dofs (a load path): rhs and
// prescribed again, K_ff kept. Throws when data prescribes other dofs than r.
void update_loads(ReducedSystem& r, const SparseMatrix& K, const Eigen::VectorXd& F, const DirichletData& data);

}  // namespace mortar
