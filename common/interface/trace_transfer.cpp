#include "common/interface/trace_transfer.hpp"

#include <Eigen/SparseLU>
#include <stdexcept>
#include <string>

namespace mortar {

std::vector<double> pointwise_transfer(const InterfaceTrace& t1, const InterfaceTrace& t2,
                                       const std::vector<double>& w2) {
  std::vector<double> w1(t1.num_nodes());
  for (int i = 0; i < t1.num_nodes(); ++i) w1[i] = t2.evaluate(w2, t1.x[i]);
  return w1;
}

std::vector<double> mortar_projection(const InterfaceTrace& t1, const InterfaceTrace& t2,
                                      const MortarMatrices& mortar, const std::vector<double>& w2) {
  const int n1 = t1.num_nodes(), n2 = t2.num_nodes();
  if (static_cast<int>(w2.size()) != n2 || mortar.M.cols() != n2 || mortar.D.cols() != n1)
    throw std::invalid_argument("mortar_projection: sizes disagree (trace 1 has " +
                                std::to_string(n1) + " nodes, trace 2 " + std::to_string(n2) + ")");
  std::vector<double> w1(n1, 0.0);
  w1.front() = w2.front();  // a1 and a2 are common nodes
  w1.back() = w2.back();
  const int interior = n1 - 2;
  if (interior == 0)
    throw std::invalid_argument(
        "mortar_projection: side 1 has a single element, so both of its nodes are end nodes and "
        "nothing is left to keep int w; use at least 2 elements");

  // D_int w1_int = M w2 - D_ends w1_ends, a square (N-1) x (N-1) banded system.
  const Eigen::Map<const Eigen::VectorXd> w2v(w2.data(), n2);
  Eigen::VectorXd ends = Eigen::VectorXd::Zero(n1);
  ends[0] = w1.front();
  ends[n1 - 1] = w1.back();
  const Eigen::VectorXd rhs = mortar.M * w2v - mortar.D * ends;
  const Eigen::SparseMatrix<double> D = mortar.D;  // column storage for the column block
  const Eigen::SparseMatrix<double> D_int = D.middleCols(1, interior);
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(D_int);
  if (lu.info() != Eigen::Success)
    throw std::runtime_error("mortar_projection: the interior block of D is singular");
  const Eigen::VectorXd w_int = lu.solve(rhs);
  for (int i = 0; i < interior; ++i) w1[i + 1] = w_int[i];
  return w1;
}

double integral(const InterfaceTrace& trace, const std::vector<double>& w) {
  double sum = 0;
  for (int e = 0; e < trace.num_elements(); ++e)
    sum += 0.5 * (trace.x[e + 1] - trace.x[e]) * (w[e] + w[e + 1]);
  return sum;
}

}  // namespace mortar
