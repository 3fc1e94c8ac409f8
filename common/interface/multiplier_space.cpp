#include "common/interface/multiplier_space.hpp"

#include <vector>

#include "common/study/profile.hpp"

namespace mortar {

MultiplierSpace end_modified_p1(const InterfaceTrace& trace1) {
  const ProfilePhase phase("interface and constraints");
  const int N = trace1.num_elements();
  MultiplierSpace space;
  std::vector<Eigen::Triplet<double>> entries;
  if (N == 1) {
    // one element holds both a1 and a2: P_{q-1} = constants
    entries.emplace_back(0, 0, 1.0);
    entries.emplace_back(0, 1, 1.0);
    space.C.resize(1, 2);
  } else {
    for (int i = 1; i <= N - 1; ++i) entries.emplace_back(i - 1, i, 1.0);
    entries.emplace_back(0, 0, 1.0);          // psi_1 takes phi_0: constant on the first element
    entries.emplace_back(N - 2, N, 1.0);      // psi_{N-1} takes phi_N: constant on the last
    space.C.resize(N - 1, N + 1);
  }
  space.C.setFromTriplets(entries.begin(), entries.end());
  return space;
}

}  // namespace mortar
