#include "cattaneo_mindlin.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace chapter08 {

namespace {
constexpr double pi = 3.14159265358979323846;
double ellipse(double X, double half_width) {
  const double t = X / half_width;
  return std::fabs(t) < 1 ? std::sqrt(1 - t * t) : 0.0;
}
}  // namespace

CattaneoMindlin::CattaneoMindlin(double P, double Q, double friction, double e_star, double R, double x0)
    : x0_(x0), F_(friction) {
  if (!(P > 0) || !(friction > 0) || Q < 0 || Q > friction * P)
    throw std::invalid_argument("Cattaneo-Mindlin needs P > 0, F > 0 and 0 <= Q <= F P");
  a_ = std::sqrt(4 * R * P / (pi * e_star));
  p0_ = 2 * P / (pi * a_);
  c_ = a_ * std::sqrt(std::max(0.0, 1 - Q / (friction * P)));
}

double CattaneoMindlin::pressure(double x) const { return p0_ * ellipse(x - x0_, a_); }

double CattaneoMindlin::shear(double x) const {
  const double X = x - x0_;
  double q = F_ * p0_ * ellipse(X, a_);
  if (c_ > 0) q -= F_ * p0_ * (c_ / a_) * ellipse(X, c_);
  return q;
}

}  // namespace chapter08
