#include "transfer_operators.hpp"

#include <cmath>
#include <vector>

#include "common/interface/merged_grid.hpp"
#include "common/interface/mortar_matrices.hpp"
#include "common/interface/trace_transfer.hpp"

namespace chapter01 {

namespace {
template <class Transfer>
Eigen::MatrixXd column_by_column(const mortar::InterfaceTrace& t1, const mortar::InterfaceTrace& t2,
                                 const Transfer& transfer) {
  Eigen::MatrixXd P(t1.num_nodes(), t2.num_nodes());
  for (int k = 0; k < t2.num_nodes(); ++k) {
    std::vector<double> hat(t2.num_nodes(), 0.0);
    hat[k] = 1.0;
    const std::vector<double> w1 = transfer(hat);
    for (int j = 0; j < t1.num_nodes(); ++j) P(j, k) = w1[j];
  }
  return P;
}

// int phi_j over a trace: the consistent nodal load of a unit uniform traction
Eigen::VectorXd hat_integrals(const mortar::InterfaceTrace& t) {
  Eigen::VectorXd F = Eigen::VectorXd::Zero(t.num_nodes());
  for (int e = 0; e < t.num_elements(); ++e) {
    F[e] += 0.5 * (t.x[e + 1] - t.x[e]);
    F[e + 1] += 0.5 * (t.x[e + 1] - t.x[e]);
  }
  return F;
}
}  // namespace

Eigen::MatrixXd mortar_matrix(const mortar::InterfaceTrace& t1, const mortar::InterfaceTrace& t2,
                              const mortar::MultiplierSpace& space) {
  const mortar::MortarMatrices mm = mortar::mortar_matrices(t1, t2, mortar::merge_traces(t1, t2), space);
  return column_by_column(t1, t2, [&](const std::vector<double>& w2) {
    return mortar::mortar_projection(t1, t2, mm, w2);
  });
}

Eigen::MatrixXd pointwise_matrix(const mortar::InterfaceTrace& t1, const mortar::InterfaceTrace& t2) {
  return column_by_column(t1, t2, [&](const std::vector<double>& w2) {
    return mortar::pointwise_transfer(t1, t2, w2);
  });
}

mortar::MultiplierSpace plain_interior_hats(const mortar::InterfaceTrace& t1) {
  const int N = t1.num_elements();
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 1; i <= N - 1; ++i) entries.emplace_back(i - 1, i, 1.0);
  mortar::MultiplierSpace space;
  space.C.resize(N - 1, N + 1);
  space.C.setFromTriplets(entries.begin(), entries.end());
  return space;
}

ForceTransfer uniform_traction_transfer(const Eigen::MatrixXd& P, const mortar::InterfaceTrace& t1,
                                        const mortar::InterfaceTrace& t2) {
  const Eigen::VectorXd F1 = hat_integrals(t1), consistent2 = hat_integrals(t2);
  const Eigen::VectorXd F2 = P.transpose() * F1;  // virtual work: F2 . w2 = F1 . (P w2)
  ForceTransfer out;
  out.total_rel_error = std::fabs(F2.sum() - F1.sum()) / F1.sum();
  out.nodal_rel_error = (F2 - consistent2).cwiseAbs().maxCoeff() / consistent2.maxCoeff();
  return out;
}

Reach reach_of_middle_hat(const Eigen::MatrixXd& P) {
  const Eigen::VectorXd column = P.col(P.cols() / 2).cwiseAbs();
  Reach r;
  r.nodes = static_cast<int>(column.size());
  const double cut = 1e-14 * column.maxCoeff();
  Eigen::Index peak = 0;
  column.maxCoeff(&peak);
  for (Eigen::Index j = 0; j < column.size(); ++j) r.nodes_reached += column[j] > cut;
  // geometric mean of |P_{j+1}| / |P_j| from two elements past the peak to one before the end
  const Eigen::Index from = peak + 2, to = column.size() - 2;
  if (to > from && column[from] > 0 && column[to] > 0)
    r.decay_per_element = std::pow(column[to] / column[from], 1.0 / static_cast<double>(to - from));
  return r;
}

}  // namespace chapter01
