#include "trace_functions.hpp"

#include <cmath>
#include <stdexcept>

namespace chapter01 {

namespace {
constexpr double pi = 3.14159265358979323846;
}

double TraceFunction::kink() const { return name == "rough" ? (std::sqrt(2.0) - 1) * L : -1.0; }

double TraceFunction::value(double x) const {
  if (name == "rough") return 1 + std::fabs(x - kink()) / L;
  return 1 + x / L + 0.5 * std::sin(2.5 * pi * x / L);
}

double TraceFunction::derivative(double x) const {
  if (name == "rough") return (x < kink() ? -1.0 : 1.0) / L;
  return 1 / L + 1.25 * pi / L * std::cos(2.5 * pi * x / L);
}

TraceFunction trace_function(const std::string& name, double L) {
  if (name != "smooth" && name != "rough")
    throw std::invalid_argument("unknown trace '" + name + "' (smooth or rough)");
  return TraceFunction{name, L};
}

}  // namespace chapter01
