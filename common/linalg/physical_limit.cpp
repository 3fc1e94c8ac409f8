#include "common/linalg/physical_limit.hpp"

#include "common/linalg/spd_solver.hpp"
#include "common/study/stopwatch.hpp"

namespace mortar {

double measure_physical_limit(const std::function<SparseMatrix()>& assemble_K) {
  const Stopwatch clock;
  const SparseMatrix K = assemble_K();
  SpdSolver solver(fastest_spd_backend());
  solver.factorize(K);
  solver.solve(Eigen::VectorXd::Ones(K.rows()));
  return clock.seconds();
}

}  // namespace mortar
