#include "marking.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace chapter10 {

std::vector<bool> doerfler_marking(const std::vector<double>& eta2, double theta) {
  if (!(theta >= 0 && theta <= 1))
    throw std::invalid_argument("doerfler_marking: theta must be in [0, 1], got " + std::to_string(theta));
  std::vector<bool> marked(eta2.size(), false);
  if (eta2.empty()) return marked;
  std::vector<int> order(eta2.size());
  std::iota(order.begin(), order.end(), 0);
  // largest first; ties in index order, so a run is reproducible
  std::stable_sort(order.begin(), order.end(), [&eta2](int a, int b) { return eta2[a] > eta2[b]; });
  const double total = std::accumulate(eta2.begin(), eta2.end(), 0.0);
  double sum = 0;
  for (std::size_t k = 0; k < order.size(); ++k) {
    const int t = order[k];
    // the largest is always marked; then stop at the share, or where the indicators are zero
    // (theta = 1 goes on to the last nonzero one: the sum in this order may fall short of the
    // total by round-off)
    if (k > 0 && ((theta < 1 && sum >= theta * total) || eta2[t] <= 0)) break;
    marked[t] = true;
    sum += eta2[t];
  }
  return marked;
}

}  // namespace chapter10
