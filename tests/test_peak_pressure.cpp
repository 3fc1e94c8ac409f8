// Chapter 5's peak-pressure reading (chapters/05_unilateral_uzawa/peak_pressure.cpp): exact on
// Hertz's ellipse, and blind to a node-to-node oscillation that moves the maximum.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "peak_pressure.hpp"

using chapter05::peak_pressure;

namespace {
// p0 sqrt(1 - (x - c)^2 / a^2) sampled at n + 1 uniform nodes of (0, 1), times (1 + wiggle) at
// every third node (the pattern of h2/h1 = 3/2).
mortar::InterfaceCurve sampled_ellipse(double p0, double a, double c, int n, double wiggle) {
  mortar::InterfaceCurve p;
  for (int i = 0; i <= n; ++i) {
    const double x = static_cast<double>(i) / n, t = (x - c) / a;
    p.x.push_back(x);
    p.value.push_back(std::fabs(t) < 1 ? p0 * std::sqrt(1 - t * t) * (i % 3 == 0 ? 1 + wiggle : 1.0) : 0.0);
  }
  return p;
}
}  // namespace

TEST(PeakPressure, returns_p0_for_an_ellipse_of_any_size) {
  // 1e-4: the P1 interpolant of the ellipse on 1536 elements, and a_h off by up to h/2
  for (const double a : {0.05, 0.1117, 0.3}) {
    const mortar::InterfaceCurve p = sampled_ellipse(0.0313, a, 0.5, 1536, 0.0);
    EXPECT_NEAR(peak_pressure(p, 0.5) / 0.0313, 1.0, 1e-4) << "a = " << a;
  }
}

TEST(PeakPressure, is_not_moved_by_a_node_to_node_oscillation) {
  // +5% at every third node: the maximum takes it, the fitted peak averages it to about 5/3%
  const mortar::InterfaceCurve p = sampled_ellipse(1.0, 0.1117, 0.5, 192, 0.05);
  const double maximum = *std::max_element(p.value.begin(), p.value.end());
  EXPECT_GT(maximum, 1.04);
  EXPECT_LT(std::fabs(peak_pressure(p, 0.5) - (1 + 0.05 / 3)), 0.005) << peak_pressure(p, 0.5);
}

TEST(PeakPressure, is_zero_without_contact) {
  const mortar::InterfaceCurve p{{0, 0.5, 1}, {0, 0, 0}};
  EXPECT_EQ(peak_pressure(p, 0.5), 0.0);
}
