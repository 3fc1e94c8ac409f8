#include "trace_functions.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace chapter01 {

namespace {
constexpr double pi = 3.14159265358979323846;
constexpr int rough_kinks = 24;
}  // namespace

std::vector<double> TraceFunction::edges() const {
  if (!has_edges()) return {};
  return {edge_center - edge_half_width, edge_center + edge_half_width};
}

double TraceFunction::value(double x) const {
  if (has_edges()) {
    const double t = (x - edge_center) / edge_half_width;
    return std::sqrt(std::max(0.0, 1 - t * t));
  }
  if (kinks.empty()) return 1 + x / L + 0.5 * std::sin(2.5 * pi * x / L);
  double sum = 0;
  for (double k : kinks) sum += std::fabs(x - k);
  return 1 + sum / (kinks.size() * L);
}

double TraceFunction::derivative(double x) const {
  if (has_edges()) {
    const double t = (x - edge_center) / edge_half_width;
    return std::fabs(t) < 1 ? -t / (edge_half_width * std::sqrt(1 - t * t)) : 0.0;
  }
  if (kinks.empty()) return 1 / L + 1.25 * pi / L * std::cos(2.5 * pi * x / L);
  double sum = 0;
  for (double k : kinks) sum += x < k ? -1.0 : 1.0;
  return sum / (kinks.size() * L);
}

TraceFunction trace_function(const std::string& name, double L) {
  TraceFunction w{name, L, {}};
  if (name == "kink") {
    w.kinks = {(std::sqrt(2.0) - 1) * L};
  } else if (name == "rough") {
    const double golden = (std::sqrt(5.0) - 1) / 2;
    for (int j = 0; j < rough_kinks; ++j) {
      const double t = 0.5 + j * golden;
      w.kinks.push_back((t - std::floor(t)) * L);
    }
  } else if (name == "edge") {
    w.edge_center = 0.5 * L;
    w.edge_half_width = 0.25 * (std::sqrt(5.0) - 1) * L;
  } else if (name != "smooth") {
    throw std::invalid_argument("unknown trace '" + name + "' (smooth, kink, rough or edge)");
  }
  return w;
}

}  // namespace chapter01
