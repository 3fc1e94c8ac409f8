#include "exercise.hpp"

namespace exercise {

std::vector<int> next_active_set(const Eigen::VectorXd& lambda, const Eigen::VectorXd& gap, double c) {
  // the right side of max(0, lambda_i - c gap_i) wins where it is positive
  std::vector<int> active;
  for (Eigen::Index i = 0; i < lambda.size(); ++i)
    if (lambda[i] - c * gap[i] > 0) active.push_back(static_cast<int>(i));
  return active;
}

Eigen::VectorXd solve_on_active_set(const Eigen::MatrixXd& S, const Eigen::VectorXd& b,
                                    const std::vector<int>& active) {
  // On A the equation is lambda_i = lambda_i - c gap_i, so gap_i = (S lambda - b)_i = 0; off A it
  // is lambda_i = 0. So S_AA lambda_A = b_A: a block of S, symmetric positive definite when the
  // rows of B are independent.
  const int a = static_cast<int>(active.size());
  Eigen::MatrixXd S_AA(a, a);
  Eigen::VectorXd b_A(a);
  for (int r = 0; r < a; ++r) {
    b_A[r] = b[active[r]];
    for (int s = 0; s < a; ++s) S_AA(r, s) = S(active[r], active[s]);
  }
  Eigen::VectorXd lambda = Eigen::VectorXd::Zero(b.size());
  if (a == 0) return lambda;
  const Eigen::VectorXd l_A = S_AA.ldlt().solve(b_A);
  for (int r = 0; r < a; ++r) lambda[active[r]] = l_A[r];
  return lambda;
}

}  // namespace exercise
