#include "common/interface/interface_trace.hpp"

#include <map>

#include <algorithm>
#include <random>
#include <stdexcept>
#include <string>

#include "common/fem/lagrange_1d.hpp"

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
  if (degree == 1) return (1 - t) * values[e] + t * values[e + 1];
  const std::array<double, 3> phi = lagrange_1d(degree, t);
  return phi[0] * values[2 * e] + phi[1] * values[2 * e + 1] + phi[2] * values[2 * e + 2];
}

Eigen::SparseMatrix<double> InterfaceTrace::mass_matrix() const {
  std::vector<Eigen::Triplet<double>> entries;
  for (int e = 0; e < num_elements(); ++e) {
    const double h = x[e + 1] - x[e];
    if (degree == 1) {
      entries.emplace_back(e, e, h / 3);
      entries.emplace_back(e + 1, e + 1, h / 3);
      entries.emplace_back(e, e + 1, h / 6);
      entries.emplace_back(e + 1, e, h / 6);
      continue;
    }
    static const double local[3][3] = {{4, 2, -1}, {2, 16, 2}, {-1, 2, 4}};
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) entries.emplace_back(2 * e + a, 2 * e + b, h * local[a][b] / 30);
  }
  Eigen::SparseMatrix<double> mass(num_dofs(), num_dofs());
  mass.setFromTriplets(entries.begin(), entries.end());
  return mass;
}

std::vector<double> InterfaceTrace::node_positions() const {
  std::vector<double> positions;
  positions.reserve(static_cast<std::size_t>(num_dofs()));
  for (int j = 0; j < num_dofs(); ++j) positions.push_back(node_x(j));
  return positions;
}

std::vector<double> InterfaceTrace::node_integrals() const {
  std::vector<double> w(static_cast<std::size_t>(num_dofs()), 0.0);
  for (int e = 0; e < num_elements(); ++e) {
    const double h = x[e + 1] - x[e];
    if (degree == 1) {
      w[e] += 0.5 * h;
      w[e + 1] += 0.5 * h;
    } else {
      w[2 * e] += h / 6;
      w[2 * e + 1] += 2 * h / 3;
      w[2 * e + 2] += h / 6;
    }
  }
  return w;
}

InterfaceTrace trace_on_side(const Mesh& mesh, Side side) {
  InterfaceTrace t;
  t.degree = mesh.degree();
  const std::vector<int>& on_side = mesh.nodes_on(side);
  for (std::size_t k = 0; k < on_side.size(); ++k) {
    // a P2 side lists end point, midpoint, end point, ...: the elements end at every other node
    if (k % t.degree == 0) t.x.push_back(mesh.nodes[on_side[k]].x());
    t.nodes.push_back(on_side[k]);
  }
  check_increasing(t);
  return t;
}

InterfaceTrace uniform_trace(double L, int n, double jitter, unsigned seed, int degree) {
  check_trace_degree(degree);
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
  }
  t.degree = degree;
  t.nodes.assign(static_cast<std::size_t>(t.num_dofs()), -1);
  check_increasing(t);
  return t;
}

std::vector<int> trace_triangles(const Mesh& mesh, const InterfaceTrace& trace) {
  std::map<std::pair<int, int>, int> element_of;  // (smaller, larger end node) -> element
  for (int e = 0; e < trace.num_elements(); ++e) {
    const int i = trace.nodes[e], j = trace.nodes[e + 1];
    element_of[{std::min(i, j), std::max(i, j)}] = e;
  }
  std::vector<int> triangle(trace.num_elements(), -1);
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    const auto& v = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const auto it = element_of.find({std::min(v[k], v[(k + 1) % 3]), std::max(v[k], v[(k + 1) % 3])});
      if (it != element_of.end()) triangle[it->second] = t;
    }
  }
  return triangle;
}

}  // namespace mortar
