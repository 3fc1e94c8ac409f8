// Where a level's time goes: a flat breakdown into phases (assembly, constraints, Dirichlet
// elimination, analysis, factorization, the dual operator S, the contact iteration, solves,
// post-processing), printed by every program's --profile.
//
// A phase is a scope: `const ProfilePhase phase("factorization");`. Times are exclusive: a phase
// opened inside another pauses the outer one, so the phases of a run add up to its total and
// no second counts twice. The library opens its own phases (SpdSolver names analysis,
// factorization and solves); a program opens the coarse ones around them. Time outside every
// phase is kept as "other".
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace mortar {

class Profile {
 public:
  // The profile the phases of this thread write to.
  static Profile& current();

  void clear();
  // Seconds per phase, in the order each phase first appeared (never "other").
  const std::vector<std::pair<std::string, double>>& phases() const { return phases_; }
  double seconds(const std::string& phase) const;  // 0 for a phase never opened
  double total() const;

  void open(const std::string& phase);
  void close();

 private:
  void charge(double now);  // the time since the last event goes to the innermost phase
  std::vector<std::pair<std::string, double>> phases_;
  std::vector<std::size_t> stack_;  // indices into phases_
  double last_ = 0;
};

class ProfilePhase {
 public:
  explicit ProfilePhase(const std::string& phase) { Profile::current().open(phase); }
  ~ProfilePhase() { Profile::current().close(); }
  ProfilePhase(const ProfilePhase&) = delete;
  ProfilePhase& operator=(const ProfilePhase&) = delete;
};

// A run's breakdown beside the physical limit's, one line per phase:
//   phase            level s   limit s
// with "other" (the level's time outside every phase) and the totals last.
struct ProfileColumn {
  std::string title;
  std::vector<std::pair<std::string, double>> phases;
  double total = 0;
};
std::string format_profile(const std::vector<ProfileColumn>& columns);
// The same as CSV (phase,<title>,...) for the benchmark script and the notes.
void write_profile_csv(const std::string& path, const std::vector<ProfileColumn>& columns);

}  // namespace mortar
