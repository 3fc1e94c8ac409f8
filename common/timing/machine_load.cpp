#include "common/timing/machine_load.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <sstream>

#include <sys/resource.h>
#include <unistd.h>

namespace mortar {

namespace {
// The first line of /proc/stat: "cpu user nice system idle iowait irq softirq steal ...", in
// clock ticks; busy is everything but idle and iowait.
double machine_busy_seconds() {
  std::ifstream stat("/proc/stat");
  std::string cpu;
  long long user = 0, nice = 0, system = 0, idle = 0, iowait = 0, irq = 0, softirq = 0, steal = 0;
  if (!(stat >> cpu >> user >> nice >> system >> idle >> iowait >> irq >> softirq >> steal) || cpu != "cpu") return 0;
  const long ticks = sysconf(_SC_CLK_TCK);
  return static_cast<double>(user + nice + system + irq + softirq + steal) / (ticks > 0 ? ticks : 100);
}

double own_cpu_seconds() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  const auto seconds = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * t.tv_usec; };
  return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

double load_average_one_minute() {
  std::ifstream loadavg("/proc/loadavg");
  double one = -1;
  return loadavg >> one ? one : -1;
}
}  // namespace

CpuClock CpuClock::now() { return {machine_busy_seconds(), own_cpu_seconds()}; }

MachineLoad machine_load(const CpuClock& start, const CpuClock& end, double own_s_all, double wall_s) {
  MachineLoad load;
  load.cores = static_cast<int>(std::max(1L, sysconf(_SC_NPROCESSORS_ONLN)));
  load.load_average = load_average_one_minute();
  const double others = end.machine_busy_s - start.machine_busy_s - own_s_all;
  if (wall_s > 0 && end.machine_busy_s > 0)
    load.other_work_share = std::clamp(others / (wall_s * load.cores), 0.0, 1.0);
  return load;
}

std::string MachineLoad::describe() const {
  char text[200];
  std::snprintf(text, sizeof text, "%d cores, load average %.2f; other work used %.0f%% of the cores: %s", cores,
                load_average, 100 * other_work_share,
                meaningful() ? "timings meaningful"
                             : "timings NOT meaningful (other work shared the cores; rerun on a quiet machine)");
  return text;
}

}  // namespace mortar
