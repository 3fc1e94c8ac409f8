#include "common/interface/multiplier_space.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <vector>

#include "common/fem/lagrange_1d.hpp"
#include "common/fem/quadrature.hpp"
#include "common/timing/profile.hpp"

namespace mortar {

MultiplierSpace end_modified_p1(const InterfaceTrace& trace1) {
  const ProfilePhase phase("interface and constraints");
  if (trace1.degree != 1)
    throw std::invalid_argument("end_modified_p1: the trace is P" + std::to_string(trace1.degree) +
                                " (end_modified_space picks the space of its degree)");
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

MultiplierSpace end_modified_p2(const InterfaceTrace& trace1) {
  const ProfilePhase phase("interface and constraints");
  const int N = trace1.num_elements();
  if (trace1.degree != 2 || N < 2)
    throw std::invalid_argument("end_modified_p2: needs a P2 trace of at least 2 elements, got degree " +
                                std::to_string(trace1.degree) + " with " + std::to_string(N));
  // rows in order along Gamma_c: x_0, then nodes 2 .. 2N - 2, then x_N (all but nodes 1, 2N - 1)
  const int rows = 2 * N - 1;
  const auto node = [&](int r) { return r == 0 ? 0 : r == rows - 1 ? 2 * N : r + 1; };
  std::vector<Eigen::Triplet<double>> entries;
  for (int r = 0; r < rows; ++r) entries.emplace_back(r, node(r), 1.0);
  // P1 on the end elements: their midpoint takes the mean of the two end values
  for (const int r : {0, 1}) entries.emplace_back(r, 1, 0.5);
  for (const int r : {rows - 2, rows - 1}) entries.emplace_back(r, 2 * N - 1, 0.5);
  MultiplierSpace space;
  space.degree = 2;
  space.C.resize(rows, 2 * N + 1);
  space.C.setFromTriplets(entries.begin(), entries.end());
  return space;
}

MultiplierSpace end_modified_space(const InterfaceTrace& trace1) {
  check_trace_degree(trace1.degree);
  return trace1.degree == 1 ? end_modified_p1(trace1) : end_modified_p2(trace1);
}

RowMajorMatrix MultiplierSpace::element_coefficients() const {
  if (!continuous()) return E;
  const int q = degree;
  const Eigen::Index elements = (C.cols() - 1) / q;
  std::vector<Eigen::Triplet<double>> entries;
  for (int i = 0; i < C.rows(); ++i)
    for (RowMajorMatrix::InnerIterator it(C, i); it; ++it) {
      // node j is local function l = j - q e of every element e that holds it: an end point
      // of two elements (right function of e - 1, left of e), a midpoint of one
      const Eigen::Index j = it.col();
      for (Eigen::Index e = std::max<Eigen::Index>(0, (j - 1) / q); e <= std::min(elements - 1, j / q); ++e)
        entries.emplace_back(i, (q + 1) * e + (j - q * e), it.value());
    }
  RowMajorMatrix out(C.rows(), (q + 1) * elements);
  out.setFromTriplets(entries.begin(), entries.end());
  return out;
}

Eigen::VectorXd integrals_against_basis(const MultiplierSpace& space, const InterfaceTrace& t,
                                        const std::function<double(double)>& f) {
  // int f phi on the local hats of every element, then psi_i = sum E(i, .) local hats
  const SegmentRule rule = gauss_legendre(3);
  const int n = t.degree + 1;  // local functions per element
  Eigen::VectorXd local = Eigen::VectorXd::Zero(n * t.num_elements());
  for (int e = 0; e < t.num_elements(); ++e) {
    const double h = t.x[e + 1] - t.x[e];
    for (std::size_t q = 0; q < rule.points.size(); ++q) {
      const double s = rule.points[q], w = rule.weights[q] * h * f(t.x[e] + s * h);
      const std::array<double, 3> phi = lagrange_1d(t.degree, s);
      for (int l = 0; l < n; ++l) local[n * e + l] += phi[l] * w;
    }
  }
  return space.element_coefficients() * local;
}

}  // namespace mortar
