#include "common/interface/multiplier_space.hpp"

#include <vector>

#include "common/fem/quadrature.hpp"
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

RowMajorMatrix MultiplierSpace::element_coefficients() const {
  if (!continuous()) return E;
  const Eigen::Index elements = C.cols() - 1;
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < C.rows(); ++i)
    for (RowMajorMatrix::InnerIterator it(C, i); it; ++it) {
      const Eigen::Index j = it.col();  // phi_j lives on elements j - 1 (as its right hat) and j (left)
      if (j > 0) entries.emplace_back(i, 2 * (j - 1) + 1, it.value());
      if (j < elements) entries.emplace_back(i, 2 * j, it.value());
    }
  RowMajorMatrix out(C.rows(), 2 * elements);
  out.setFromTriplets(entries.begin(), entries.end());
  return out;
}

Eigen::VectorXd integrals_against_basis(const MultiplierSpace& space, const InterfaceTrace& t,
                                        const std::function<double(double)>& f) {
  // int f phi on the local hats of every element, then psi_i = sum E(i, .) local hats
  const SegmentRule rule = gauss_legendre(3);
  Eigen::VectorXd local = Eigen::VectorXd::Zero(2 * t.num_elements());
  for (int e = 0; e < t.num_elements(); ++e) {
    const double h = t.x[e + 1] - t.x[e];
    for (std::size_t q = 0; q < rule.points.size(); ++q) {
      const double s = rule.points[q], w = rule.weights[q] * h * f(t.x[e] + s * h);
      local[2 * e] += (1 - s) * w;
      local[2 * e + 1] += s * w;
    }
  }
  return space.element_coefficients() * local;
}

}  // namespace mortar
