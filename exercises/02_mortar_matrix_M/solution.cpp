#include <algorithm>
#include <cmath>

#include "exercise.hpp"

namespace exercise {

namespace {
// index e of the element [x_e, x_{e+1}] that contains the point
int element_of(const std::vector<double>& x, double point) {
  const int e = static_cast<int>(std::upper_bound(x.begin(), x.end(), point) - x.begin()) - 1;
  return std::clamp(e, 0, static_cast<int>(x.size()) - 2);
}
}  // namespace

Eigen::MatrixXd mixed_mass(const std::vector<double>& x1, const std::vector<double>& x2) {
  std::vector<double> breaks(x1);
  breaks.insert(breaks.end(), x2.begin(), x2.end());
  std::sort(breaks.begin(), breaks.end());
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(x1.size()),
                                            static_cast<Eigen::Index>(x2.size()));
  const double g = 0.5 / std::sqrt(3.0);  // 2-point Gauss on [0, 1]: 1/2 -+ g, weights 1/2
  for (std::size_t s = 0; s + 1 < breaks.size(); ++s) {
    const double a = breaks[s], b = breaks[s + 1];
    if (b - a <= 1e-12 * (x1.back() - x1.front())) continue;  // a merged pair: no segment
    const int e1 = element_of(x1, 0.5 * (a + b)), e2 = element_of(x2, 0.5 * (a + b));
    for (double t : {0.5 - g, 0.5 + g}) {
      const double x = a + t * (b - a), w = 0.5 * (b - a);
      const double s1 = (x - x1[e1]) / (x1[e1 + 1] - x1[e1]), s2 = (x - x2[e2]) / (x2[e2 + 1] - x2[e2]);
      const double phi1[2] = {1 - s1, s1}, phi2[2] = {1 - s2, s2};
      for (int j = 0; j < 2; ++j)
        for (int k = 0; k < 2; ++k) P(e1 + j, e2 + k) += w * phi1[j] * phi2[k];
    }
  }
  return P;
}

}  // namespace exercise
