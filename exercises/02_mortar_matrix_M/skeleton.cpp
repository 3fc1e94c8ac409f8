#include "exercise.hpp"

namespace exercise {

Eigen::MatrixXd mixed_mass(const std::vector<double>& x1, const std::vector<double>& x2) {
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(x1.size()),
                                            static_cast<Eigen::Index>(x2.size()));
  // Your code here: loop over the segments of the merged grid; on each, find the element of
  // each grid that contains it, and add 2-point Gauss contributions of phi^1_j phi^2_k.
  return P;
}

}  // namespace exercise
