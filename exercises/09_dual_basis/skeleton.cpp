#include "exercise.hpp"

namespace exercise {

Eigen::Matrix2d dual_element_coefficients(double h, double theta) {
  // Your code here. The identity below gives back the hats themselves, which are not
  // biorthogonal (and nothing is refused yet).
  (void)h;
  (void)theta;
  return Eigen::Matrix2d::Identity();
}

}  // namespace exercise
