#include "common/linalg/physical_limit.hpp"

#include <algorithm>
#include <cstdlib>
#include <string>

#include "common/linalg/memory_estimate.hpp"
#include "common/linalg/spd_solver.hpp"
#include "common/timing/stopwatch.hpp"

namespace mortar {

double measure_physical_limit(const std::function<SparseMatrix()>& assemble_K) {
  const Stopwatch clock;
  SparseMatrix K;
  {
    const ProfilePhase phase("assembly");
    K = assemble_K();
  }
  SpdSolver solver(fastest_spd_backend());
  solver.factorize(K);
  solver.solve(Eigen::VectorXd::Ones(K.rows()));
  return clock.seconds();
}

namespace {
bool time_once() {
  const char* value = std::getenv("MORTAR_TIME_ONCE");
  return value != nullptr && std::string(value) == "1";
}

// One timed run with its phases and its resident-set peak.
struct Timing {
  double seconds = 0, peak_bytes = 0;
  ProfileColumn profile;
};

Timing timed(const std::string& title, const std::function<double()>& run) {
  Profile::current().clear();
  reset_peak_memory();
  Timing t;
  t.seconds = run();
  t.peak_bytes = peak_memory_bytes();
  t.profile = {title, Profile::current().phases(), t.seconds};
  Profile::current().clear();
  return t;
}

// Keeps the fastest timing and the spread of all.
// The smallest peak is kept too: a later repetition also holds what the one before left.
struct Series {
  Timing best;
  double slowest = 0, least_peak = 0;
  void add(Timing t) {
    least_peak = least_peak == 0 ? t.peak_bytes : std::min(least_peak, t.peak_bytes);
    slowest = std::max(slowest, t.seconds);
    if (best.seconds == 0 || t.seconds < best.seconds) best = std::move(t);
  }
  double spread() const { return best.seconds > 0 ? (slowest - best.seconds) / best.seconds : 0.0; }
};
}  // namespace

TimedLevel time_against_limit(const std::function<void()>& level,
                              const std::function<SparseMatrix()>& assemble_K, Repetitions repetitions) {
  if (time_once()) repetitions = {1, 1, 0.0};
  Series run, limit;
  TimedLevel t;
  const Stopwatch clock;
  while (t.repeats < repetitions.max &&
         (t.repeats < repetitions.min || clock.seconds() < repetitions.budget_s)) {
    run.add(timed("level", [&] {
      const Stopwatch c;
      level();
      return c.seconds();
    }));
    limit.add(timed("limit", [&] { return measure_physical_limit(assemble_K); }));
    ++t.repeats;
  }
  t.time_s = run.best.seconds;
  t.limit_s = limit.best.seconds;
  t.time_spread = run.spread();
  t.limit_spread = limit.spread();
  t.peak_bytes = run.least_peak;
  t.limit_peak_bytes = limit.least_peak;
  t.profile = run.best.profile;
  t.limit_profile = limit.best.profile;
  return t;
}

}  // namespace mortar
