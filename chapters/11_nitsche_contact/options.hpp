// Chapter 11's options, checked before any work starts (status 2 with a message naming the
// option otherwise).
#pragma once

#include <string>

#include "common/study/bilateral_study.hpp"
#include "common/study/options.hpp"

namespace chapter11 {

struct Options : mortar::TwoBodyOptions {
  Options() {  // chapter 5's hertz-exact scene: one material, square blocks
    E2 = 1;
    nu2 = 0.3;
    H1 = H2 = 1;
  }
  std::string scene = "hertz-exact";
  double theta = 1;      // Nitsche's variant: 1, 0 or -1
  // Nitsche: gamma = gamma0 E / h. theta = 1 needs gamma0 above a threshold, measured between 1
  // and 2.15 on every level (EVIDENCE.md, "gamma0"); 5 leaves a margin of 2.3 or more.
  double gamma0 = 5;
  double penalty_gamma0 = 5;  // penalty: gamma0 unless given (the same gamma, without consistency)
  std::string traction = "body1";  // whose traction Nitsche reads: body1, body2, mean, harmonic
  double R = 1;
  int n0 = 4, levels = 7;
  // Krylov iterations (krylov.hpp) on levels up to this many unknowns: at 191k, five of them cost
  // 50 s, more than every solve of the level together
  double krylov_max_dofs = 60000;
  std::string gap = "exact";  // or "interpolated": g's linear interpolant on each level's merged grid
  std::string linear_solver = "condensed";  // each Newton step's solve (common/contact/nitsche_steps.hpp)
  std::string start = "nested";  // Nitsche and penalty: from the level below, or "cold" (u = 0 inside)
  std::string sweep = "none";  // "gamma0": errors and Newton steps against gamma0 for every theta
  int sweep_level = 4;
  std::string out = "results/ch11_nitsche_contact";
  bool quick = false, no_plot = false;
  int threads = mortar::default_solver_threads();
};

void parse_options(mortar::OptionParser& parser, Options& o, int argc, char** argv);

// The weight w of body 1's traction in p(u) = w p^1 + (1 - w) p^2 for --traction body1, body2
// or mean (harmonic weighs each segment by its own h1 and h2: NitscheOptions::harmonic_weight).
double body1_weight(const Options& o);

}  // namespace chapter11
