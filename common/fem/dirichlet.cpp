#include "common/fem/dirichlet.hpp"

#include <stdexcept>
#include <string>

#include "common/timing/profile.hpp"

namespace mortar {

void prescribe_on_sides(DirichletData& data, const Mesh& mesh, const std::vector<Side>& sides,
                        const VectorField& g) {
  for (Side side : sides)
    for (int a : mesh.nodes_on(side)) {
      const Eigen::Vector2d value = g(mesh.nodes[a]);
      for (int c = 0; c < 2; ++c) {
        data.dofs.push_back(2 * a + c);
        data.values.push_back(value[c]);
      }
    }
}

Eigen::VectorXd ReducedSystem::expand(const Eigen::VectorXd& u_free) const {
  Eigen::VectorXd u = prescribed;
  for (size_t i = 0; i < free_dofs.size(); ++i) u[free_dofs[i]] = u_free[static_cast<int>(i)];
  return u;
}

ReducedSystem eliminate_dirichlet(const SparseMatrix& K, const Eigen::VectorXd& F,
                                  const DirichletData& data) {
  const ProfilePhase phase("Dirichlet elimination");
  const int n = static_cast<int>(K.rows());
  if (K.cols() != n || F.size() != n)
    throw std::invalid_argument("eliminate_dirichlet: K is " + std::to_string(K.rows()) + " x " +
                                std::to_string(K.cols()) + ", F has " + std::to_string(F.size()));
  if (data.dofs.size() != data.values.size())
    throw std::invalid_argument("eliminate_dirichlet: dofs and values differ in length");

  ReducedSystem r;
  r.prescribed = Eigen::VectorXd::Zero(n);
  std::vector<bool> fixed(n, false);
  for (size_t k = 0; k < data.dofs.size(); ++k) {
    const int d = data.dofs[k];
    if (d < 0 || d >= n) throw std::invalid_argument("eliminate_dirichlet: dof " + std::to_string(d) + " out of range");
    fixed[d] = true;
    r.prescribed[d] = data.values[k];
  }
  r.full_to_free.assign(n, -1);
  for (int d = 0; d < n; ++d)
    if (!fixed[d]) {
      r.full_to_free[d] = static_cast<int>(r.free_dofs.size());
      r.free_dofs.push_back(d);
    }

  // F_f - K_fd u_d, then K_ff: one pass over the columns of K.
  const Eigen::VectorXd Ku_d = K * r.prescribed;
  const int nf = static_cast<int>(r.free_dofs.size());
  r.rhs.resize(nf);
  for (int i = 0; i < nf; ++i) r.rhs[i] = F[r.free_dofs[i]] - Ku_d[r.free_dofs[i]];

  r.K.resize(nf, nf);
  r.K.reserve(K.nonZeros());
  for (int j = 0; j < nf; ++j) {
    r.K.startVec(j);
    for (SparseMatrix::InnerIterator it(K, r.free_dofs[j]); it; ++it) {
      const int i = r.full_to_free[it.row()];
      if (i >= 0) r.K.insertBack(i, j) = it.value();
    }
  }
  r.K.finalize();
  return r;
}

void update_loads(ReducedSystem& r, const SparseMatrix& K, const Eigen::VectorXd& F, const DirichletData& data) {
  const int n = static_cast<int>(K.rows());
  if (F.size() != n || static_cast<int>(r.full_to_free.size()) != n || data.dofs.size() != data.values.size())
    throw std::invalid_argument("update_loads: sizes do not match the reduced system");
  r.prescribed = Eigen::VectorXd::Zero(n);
  for (std::size_t k = 0; k < data.dofs.size(); ++k) {
    const int d = data.dofs[k];
    if (d < 0 || d >= n || r.full_to_free[d] >= 0)
      throw std::invalid_argument("update_loads: dof " + std::to_string(d) + " is not prescribed in this system");
    r.prescribed[d] = data.values[k];
  }
  const Eigen::VectorXd Ku_d = K * r.prescribed;
  for (std::size_t i = 0; i < r.free_dofs.size(); ++i) r.rhs[i] = F[r.free_dofs[i]] - Ku_d[r.free_dofs[i]];
}

}  // namespace mortar
