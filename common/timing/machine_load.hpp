// How busy the machine was while a program timed itself: a wall time means what it says only
// when no other work shared the cores. Linux's /proc/stat counts the CPU time of every process;
// the program's own (all its ranks, from getrusage) taken away leaves the others'.
#pragma once

#include <string>

namespace mortar {

// The machine's CPU time spent outside idle, and this process's own CPU time, at one moment.
struct CpuClock {
  double machine_busy_s = 0;  // every process, from /proc/stat (0 where it cannot be read)
  double own_s = 0;           // this process, user and system (getrusage)
  static CpuClock now();
};

struct MachineLoad {
  int cores = 1;
  double load_average = 0;       // /proc/loadavg, one minute (-1 where it cannot be read)
  double other_work_share = 0;   // CPU time of other processes / (wall time x cores), 0 to 1
  bool meaningful() const { return other_work_share <= 0.1; }
  // e.g. "2 cores, load average 1.93; other work used 3% of the cores: timings meaningful"
  std::string describe() const;
};

// The load between `start` and now, over `wall_s` seconds; own_s_all is the CPU time of every
// process of the program since `start` (the sum over MPI ranks: each rank one CpuClock).
MachineLoad machine_load(const CpuClock& start, const CpuClock& end, double own_s_all, double wall_s);

}  // namespace mortar
