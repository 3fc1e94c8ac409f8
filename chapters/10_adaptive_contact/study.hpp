// What chapter 10 reads off its two runs (adaptive and uniform): the error of every step, the
// rates in N, the effectivity band, the time to an error of 1 %, and for the punch the
// reference the errors are measured against.
#pragma once

#include <map>
#include <string>

#include "adaptive_loop.hpp"
#include "common/study/convergence_study.hpp"
#include "common/study/json_writer.hpp"

namespace chapter10 {

// Without an exact solution (the punch) the energy error comes from the strain energy: for a
// problem driven by prescribed displacements alone, W(u_h) - W(u) = 1/2 ||u - u_h||^2 up to the
// consistency error of the mortar constraint (a product of two errors), so
// ||u - u_h|| / ||u|| = (|W_h - W| / W)^(1/2). W comes from steps the reported ones do not
// include: the loop runs on past --target (to half of it, about 4 times the unknowns), and
// W is extrapolated from those further steps alone, W_k = W + C / N_k (an optimal adaptive
// sequence has ||u - u_h||^2 ~ 1/N). So the rate measured on the reported steps does not come
// out of the fit that made the reference.
struct EnergyReference {
  double W = 0;          // the extrapolated strain energy
  double W_finest = 0;   // the finest step's, beside it
  int steps_fitted = 0, dofs_from = 0, dofs_to = 0;
};
// Moves the steps after the first whose estimated error is below `target` out of run.steps and
// fits W on them (on the last four steps when fewer than three are left over).
EnergyReference split_off_reference(LoopResult& run, double target);
// Fills err_energy, rel_err_energy and effectivity from the reference.
void measure_against_reference(LoopResult& run, const EnergyReference& ref);

// One row per step: step, h (the mean size (area / triangles)^(1/2)), dofs, ..., err_energy
// (relative), estimator (relative, same norm), effectivity, each term's share, time_s.
mortar::ConvergenceTable step_table(const LoopResult& run);

// -d log(err) / d log(N), least squares over the rows whose N is within a factor 16 of the
// last one (the span of three uniform levels; adaptive steps are closer together, and a fit
// over three of them moves by +-0.05 from step to step). 0.5 is the optimal rate of P1.
double rate_in_n(const LoopResult& run, const std::string& what);

// The wall time to the first step whose relative energy error is at most `error` (NaN when
// none is); adaptive: every step up to it, uniform: that level alone.
double time_to_error(const LoopResult& run, double error);
int dofs_at_error(const LoopResult& run, double error);

// The pressure's exponent s in p ~ r^s next to a corner of the punch at x_corner, fitted on the
// nodes at distances in [r_min, r_max] from it.
double pressure_exponent(const ContactStep& step, double x_corner, double r_min, double r_max);

}  // namespace chapter10
