// Chapter 8's reference for the cattaneo scene (chapters/08_friction/cattaneo_mindlin.cpp)
// against values computed by hand from Hertz's and Cattaneo's formulas (Johnson, Contact
// Mechanics, 4.3 and 7.2). With R = 1, E* = pi and P = 1 the numbers are simple:
// a = sqrt(4 R P / (pi E*)) = 2/pi, p0 = 2 P / (pi a) = 1; with F = 1/2 and Q = 1/4,
// c / a = sqrt(1 - Q / (F P)) = 1/sqrt(2).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "cattaneo_mindlin.hpp"

namespace {
constexpr double pi = 3.14159265358979323846;
const double x0 = 0.3, a = 2 / pi;
const chapter08::CattaneoMindlin reference(1.0, 0.25, 0.5, pi, 1.0, x0);
}  // namespace

TEST(CattaneoMindlin, half_widths_and_peak_are_hertz_and_cattaneo) {
  EXPECT_NEAR(reference.half_width(), a, 1e-15);
  EXPECT_NEAR(reference.peak_pressure(), 1.0, 1e-15);
  EXPECT_NEAR(reference.stick_half_width(), a / std::sqrt(2.0), 1e-15);
}

// p(X) = p0 sqrt(1 - X^2/a^2): 1 at the centre, sqrt(3)/2 at X = a/2, 0.6 at X = 0.8 a, none
// outside. A stray factor in the pressure (F, say) changes every one of them.
TEST(CattaneoMindlin, pressure_is_hertzs_at_hand_computed_points) {
  EXPECT_NEAR(reference.pressure(x0), 1.0, 1e-15);
  EXPECT_NEAR(reference.pressure(x0 + 0.5 * a), std::sqrt(3.0) / 2, 1e-15);
  EXPECT_NEAR(reference.pressure(x0 - 0.8 * a), 0.6, 1e-15);
  EXPECT_EQ(reference.pressure(x0 + 1.01 * a), 0.0);
}

// q = F p0 (sqrt(1 - X^2/a^2) - (c/a) sqrt(1 - X^2/c^2)) on |X| < c, F p on the slip zone:
// (1 - 1/sqrt(2)) / 2 at the centre; at X = a/2 (stick, X^2/c^2 = 1/2) (sqrt(3)/2 - 1/2) / 2;
// at X = 0.8 a (slip) F p = 0.3; none outside.
TEST(CattaneoMindlin, shear_is_cattaneos_at_hand_computed_points) {
  EXPECT_NEAR(reference.shear(x0), 0.5 * (1 - 1 / std::sqrt(2.0)), 1e-15);
  EXPECT_NEAR(reference.shear(x0 + 0.5 * a), 0.5 * (std::sqrt(3.0) / 2 - 0.5), 1e-15);
  EXPECT_NEAR(reference.shear(x0 - 0.8 * a), 0.3, 1e-15);
  EXPECT_EQ(reference.shear(x0 - 1.01 * a), 0.0);
  // no shear: q = 0 everywhere (c = a); gross sliding: q = F p (c = 0)
  const chapter08::CattaneoMindlin none(1.0, 0.0, 0.5, pi, 1.0, x0), full(1.0, 0.5, 0.5, pi, 1.0, x0);
  EXPECT_NEAR(none.shear(x0 + 0.5 * a), 0.0, 1e-15);
  EXPECT_NEAR(full.shear(x0 + 0.5 * a), 0.5 * std::sqrt(3.0) / 2, 1e-15);
}

TEST(CattaneoMindlin, refuses_a_shear_beyond_f_p) {
  EXPECT_THROW(chapter08::CattaneoMindlin(1.0, 0.6, 0.5, pi, 1.0, x0), std::invalid_argument);
  EXPECT_THROW(chapter08::CattaneoMindlin(0.0, 0.0, 0.5, pi, 1.0, x0), std::invalid_argument);
}
