// The physical limit of one level (README.md, "Speed"): assembling K plus one factorization
// and one solve of K with the fastest sparse Cholesky available, timed in the same run on the
// same matrix, with no coupling and no iteration. Programs report their own time as a ratio
// to it.
//
// On a loaded machine one timing of each, minutes apart, can make that ratio anything (0.25 and
// 5.1 have been seen). So the level and its limit are timed the same way: interleaved (level,
// limit, level, limit, ...), at least twice each, and the minimum of each is kept, with the
// spread (max - min) / min that says how far to trust it.
#pragma once

#include <functional>

#include "common/fem/p1_elasticity.hpp"
#include "common/timing/profile.hpp"

namespace mortar {

// assemble_K builds the SPD matrix of the level (both bodies, Dirichlet dofs eliminated).
// Returns seconds for assemble_K() + factorize + one solve.
double measure_physical_limit(const std::function<SparseMatrix()>& assemble_K);

struct TimedLevel {
  double time_s = 0, limit_s = 0;            // the minimum over the repetitions
  double time_spread = 0, limit_spread = 0;  // (max - min) / min over the repetitions
  int repeats = 0;                           // of each
  double peak_bytes = 0, limit_peak_bytes = 0;  // resident-set peak during each (0: unknown)
  ProfileColumn profile, limit_profile;      // the phases of the fastest repetition of each
  double ratio() const { return time_s / limit_s; }
};

// How often: at least `min` times each, then more while the level and its limit together
// have taken less than `budget_s` (small levels, where one timing is noisy: with two threads
// the spread of two runs reached 20-50% below a second), at most `max`. With the environment
// variable MORTAR_TIME_ONCE=1, once each whatever these say: the test suite sets it for the
// runs under the sanitizers (tests/CMakeLists.txt), where time means nothing and every
// repetition costs.
struct Repetitions {
  int min = 2, max = 5;
  double budget_s = 1.0;
};

// Runs `level` (the program's whole solve of one level; it keeps its own result) and the
// limit of assemble_K interleaved, as above: the level first, so assemble_K may use what the
// level set up (its scene).
TimedLevel time_against_limit(const std::function<void()>& level,
                              const std::function<SparseMatrix()>& assemble_K,
                              Repetitions repetitions = {});

}  // namespace mortar
