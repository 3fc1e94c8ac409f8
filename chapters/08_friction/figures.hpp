// Chapter 8's figures (README.md, "Figures"): the two bodies and their coarsest meshes, the
// stick, slip and open nodes along Gamma_c with
// the shear and its bounds, errors against h and against time, the Newton residuals of every
// load step, and (cattaneo) the stick zone against Q / (F P).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "common/study/convergence_study.hpp"
#include "frictional_level.hpp"
#include "study.hpp"

namespace chapter08 {

// The exact curves a zones figure draws beside the computed ones (empty functions: none).
struct ExactCurves {
  std::function<double(double)> shear, bound;  // lambda_t and its threshold s
  std::string label;
  double x_min = 0, x_max = 0;  // the window; equal: the whole Gamma_c
};
// The scene before any result: both bodies with the coarsest level's meshes, their traces on
// Gamma_c and the multiplier nodes of the non-mortar side (meshes.png).
void plot_meshes(const std::string& folder, const FrictionalLevel& coarsest, const Options& o, bool run);
void plot_zones(const std::string& folder, const FrictionalLevel& r, const Options& o, const ExactCurves& exact,
                bool run);
void plot_errors(const std::string& folder, const mortar::ConvergenceTable& table, const Options& o, bool run);
void plot_newton(const std::string& folder, const Options& o, const FrictionalLevel& r, bool run);
void plot_stick_zone(const std::string& folder, const Options& o, const std::vector<CattaneoStep>& steps, double a,
                     bool run);

}  // namespace chapter08
