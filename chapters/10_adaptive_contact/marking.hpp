// MARK: Doerfler's bulk criterion (Doerfler 1996). Given the squared indicators eta_T^2 of every
// triangle of both bodies and theta in [0, 1], the smallest set M whose indicators carry the
// share theta of the whole: sum_{T in M} eta_T^2 >= theta sum_T eta_T^2. Taking the largest
// indicators first gives the smallest such set. theta = 1 marks every triangle whose indicator
// is not zero; theta = 0 would mark nothing and the loop would stop refining, so at least the
// largest one is marked.
#pragma once

#include <vector>

namespace chapter10 {

std::vector<bool> doerfler_marking(const std::vector<double>& eta2, double theta);

}  // namespace chapter10
