#include "partial_coverage.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "common/interface/dual_basis.hpp"
#include "common/interface/merged_grid.hpp"
#include "common/interface/mortar_matrices.hpp"

namespace chapter06 {

namespace {
// The merged grid of two traces restricted to where both exist, (0, min of their ends).
mortar::MergedGrid overlap_grid(const mortar::InterfaceTrace& t1, const mortar::InterfaceTrace& t2) {
  const double end = std::min(t1.x.back(), t2.x.back());
  std::vector<double> points(t1.x.begin(), t1.x.end());
  points.insert(points.end(), t2.x.begin(), t2.x.end());
  std::sort(points.begin(), points.end());
  mortar::MergedGrid grid;
  for (double p : points)
    if (p <= end && (grid.breakpoints.empty() || p - grid.breakpoints.back() > 1e-12)) grid.breakpoints.push_back(p);
  for (std::size_t k = 0; k + 1 < grid.breakpoints.size(); ++k) {
    mortar::MergedSegment s;
    s.a = grid.breakpoints[k];
    s.b = grid.breakpoints[k + 1];
    s.element1 = t1.element_containing(0.5 * (s.a + s.b));
    s.element2 = t2.element_containing(0.5 * (s.a + s.b));
    grid.segments.push_back(s);
  }
  return grid;
}
}  // namespace

std::vector<PartialCoverage> partial_coverage(int n, const std::vector<double>& thetas) {
  const mortar::InterfaceTrace t1 = mortar::uniform_trace(1.0, n);
  const double h = 1.0 / n;
  const mortar::MultiplierSpace space = mortar::dual_end_modified_p1(t1);
  std::vector<PartialCoverage> out;
  for (double theta : thetas) {
    const double end = t1.x[n - 2] + theta * h;
    const int n2 = std::max(2, static_cast<int>(std::lround(end / (1.5 * h))));
    const mortar::InterfaceTrace t2 = mortar::uniform_trace(end, n2);
    const mortar::MortarMatrices mm = mortar::mortar_matrices(t1, t2, overlap_grid(t1, t2), space);
    PartialCoverage c;
    c.covered = theta;
    c.offdiagonal = mortar::d_offdiagonal_max(space, mm.D);
    // int phi_i over the covered part: the row sums of int phi_i phi_j (sum_j phi_j = 1)
    mortar::MultiplierSpace hats;
    std::vector<Eigen::Triplet<double>> ones;
    for (int i = 1; i <= n - 1; ++i) ones.emplace_back(i - 1, i, 1.0);
    hats.C.resize(n - 1, n + 1);
    hats.C.setFromTriplets(ones.begin(), ones.end());
    const Eigen::VectorXd hat_integrals =
        Eigen::MatrixXd(mortar::mortar_matrices(t1, t2, overlap_grid(t1, t2), hats).D).rowwise().sum();
    for (int i = 0; i < n - 1; ++i)
      if (hat_integrals[i] > 1e-14 * h)
        c.diagonal_ratio_min = std::min(c.diagonal_ratio_min, mm.D.coeff(i, i + 1) / hat_integrals[i]);
    // D w1 = M 1 on the interior nodes, the end node 0 given (= 1); node n is not covered, so
    // its column is zero. Rows: psi_1 .. psi_{n-1}, unknowns w1 at nodes 1 .. n-1.
    const Eigen::MatrixXd D = Eigen::MatrixXd(mm.D);
    const Eigen::VectorXd rhs = Eigen::MatrixXd(mm.M).rowwise().sum() - D.col(0);
    const Eigen::MatrixXd D_interior = D.block(0, 1, n - 1, n - 1);
    const Eigen::VectorXd full = D_interior.fullPivLu().solve(rhs);
    const Eigen::VectorXd diagonal = rhs.cwiseQuotient(D_interior.diagonal());
    // the covered nodes: x_j <= end
    for (int j = 1; j <= n - 1; ++j) {
      if (t1.x[j] > end + 1e-12) break;
      c.constant_error_full = std::max(c.constant_error_full, std::fabs(full[j - 1] - 1));
      c.constant_error_diagonal = std::max(c.constant_error_diagonal, std::fabs(diagonal[j - 1] - 1));
    }
    out.push_back(c);
  }
  return out;
}

void write_partial_coverage_csv(const std::string& path, const std::vector<PartialCoverage>& cases) {
  std::ofstream f(path);
  f << "covered_fraction,d_offdiagonal_max,diagonal_ratio_min,constant_error_full_D,constant_error_diagonal_D\n";
  for (const PartialCoverage& c : cases)
    f << c.covered << "," << c.offdiagonal << "," << c.diagonal_ratio_min << "," << c.constant_error_full << ","
      << c.constant_error_diagonal << "\n";
  if (!f) throw std::runtime_error("cannot write " + path);
}

}  // namespace chapter06
