#include "common/interface/interface_trace.hpp"

#include <algorithm>
#include <random>
#include <stdexcept>
#include <string>

namespace mortar {

namespace {
void check_increasing(const InterfaceTrace& t) {
  if (t.num_nodes() < 2)
    throw std::invalid_argument("interface trace: need at least 2 nodes, got " +
                                std::to_string(t.num_nodes()));
  for (int i = 0; i + 1 < t.num_nodes(); ++i)
    if (!(t.x[i + 1] > t.x[i]))
      throw std::invalid_argument("interface trace: element " + std::to_string(i) +
                                  " has non-positive length " + std::to_string(t.x[i + 1] - t.x[i]) +
                                  " at x = " + std::to_string(t.x[i]));
}
}  // namespace

double InterfaceTrace::max_element_length() const {
  double h = 0;
  for (int i = 0; i + 1 < num_nodes(); ++i) h = std::max(h, x[i + 1] - x[i]);
  return h;
}

int InterfaceTrace::element_containing(double point) const {
  const auto it = std::upper_bound(x.begin(), x.end(), point);
  const int e = static_cast<int>(it - x.begin()) - 1;
  return std::clamp(e, 0, num_elements() - 1);
}

double InterfaceTrace::evaluate(const std::vector<double>& values, double point) const {
  const int e = element_containing(point);
  const double t = (point - x[e]) / (x[e + 1] - x[e]);
  return (1 - t) * values[e] + t * values[e + 1];
}

Eigen::SparseMatrix<double> InterfaceTrace::mass_matrix() const {
  std::vector<Eigen::Triplet<double>> entries;
  for (int e = 0; e < num_elements(); ++e) {
    const double h = x[e + 1] - x[e];
    entries.emplace_back(e, e, h / 3);
    entries.emplace_back(e + 1, e + 1, h / 3);
    entries.emplace_back(e, e + 1, h / 6);
    entries.emplace_back(e + 1, e, h / 6);
  }
  Eigen::SparseMatrix<double> mass(num_nodes(), num_nodes());
  mass.setFromTriplets(entries.begin(), entries.end());
  return mass;
}

InterfaceTrace trace_on_side(const Mesh& mesh, Side side) {
  InterfaceTrace t;
  for (int a : mesh.nodes_on(side)) {
    t.x.push_back(mesh.nodes[a].x());
    t.nodes.push_back(a);
  }
  check_increasing(t);
  return t;
}

InterfaceTrace uniform_trace(double L, int n, double jitter, unsigned seed) {
  if (!(L > 0) || n < 1)
    throw std::invalid_argument("uniform_trace: need L > 0 and n >= 1, got L = " +
                                std::to_string(L) + ", n = " + std::to_string(n));
  if (!(jitter >= 0 && jitter <= 0.4))
    throw std::invalid_argument("uniform_trace: jitter must be in [0, 0.4], got " +
                                std::to_string(jitter));
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> shift(-0.5 * jitter, 0.5 * jitter);
  InterfaceTrace t;
  const double h = L / n;
  for (int i = 0; i <= n; ++i) {
    const double move = (i > 0 && i < n && jitter > 0) ? shift(rng) * h : 0.0;
    t.x.push_back(i * h + move);
    t.nodes.push_back(-1);
  }
  check_increasing(t);
  return t;
}

}  // namespace mortar
