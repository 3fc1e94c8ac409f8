#include "common/linalg/memory_estimate.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <thread>

namespace mortar {

namespace {
constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double gigabyte = 1e9;
// The fixed part per hardware thread: 360 MB measured on 2 threads, rounded up.
constexpr double fixed_bytes_per_thread = 200e6;

std::string gb(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g GB", bytes / gigabyte);
  return text;
}
}  // namespace

double run_bytes(double dofs, double bytes_per_dof) {
  const double threads = std::max(1u, std::thread::hardware_concurrency());
  return threads * fixed_bytes_per_thread + dofs * bytes_per_dof;
}

double MachineMemory::usable() const { return std::min(available_bytes, address_limit_bytes); }

std::string MachineMemory::describe() const {
  std::string text = std::isinf(available_bytes) ? std::string("available memory unknown")
                                                 : gb(available_bytes) + " available";
  if (!std::isinf(address_limit_bytes)) text += ", address space limited to " + gb(address_limit_bytes) + " (ulimit -v)";
  return text;
}

double mem_available_bytes(const std::string& meminfo) {
  std::istringstream lines(meminfo);
  std::string key, unit;
  double value = 0;
  while (lines >> key >> value) {
    std::getline(lines, unit);
    if (key == "MemAvailable:") return value * 1024;  // the kernel counts in kB = 1024 bytes
  }
  return inf;
}

MachineMemory machine_memory() {
  MachineMemory m{inf, inf};
  std::ifstream f("/proc/meminfo");
  if (f) {
    std::stringstream text;
    text << f.rdbuf();
    m.available_bytes = mem_available_bytes(text.str());
  }
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
    m.address_limit_bytes = static_cast<double>(limit.rlim_cur);
  return m;
}

std::string memory_shortfall(double dofs, double bytes_per_dof, const MachineMemory& machine) {
  const double needed = run_bytes(dofs, bytes_per_dof);
  if (needed <= machine.usable()) return "";
  char text[96];
  std::snprintf(text, sizeof text, "the finest level would have %.3g dofs and need about ", dofs);
  return text + gb(needed) + " of memory; this machine has " + machine.describe() +
         ": use fewer --levels or a smaller --n0";
}

double dense_bytes(double rows, double cols) { return 8 * rows * cols; }

double schur_dense_bytes(double m, double t) {
  const double nc = m + t;
  return 2 * dense_bytes(nc, nc) + dense_bytes(nc, m) + dense_bytes(m, m);
}

double elimination_dense_bytes(double m, double t) {
  // dense B_r and X (8 bytes an entry), X as triplets (16) and sparse (12): 44 bytes per entry
  // of m x t; the t x t block: dense, triplets twice, sparse, and its factor (64 bytes)
  return 5.5 * dense_bytes(m, t) + 8 * dense_bytes(t, t);
}

std::string memory_shortfall(const std::vector<MemoryPart>& parts, const MachineMemory& machine,
                             const std::string& advice) {
  double needed = run_bytes(0, 0);
  const MemoryPart* largest = nullptr;
  for (const MemoryPart& p : parts) {
    needed += p.bytes;
    if (largest == nullptr || p.bytes > largest->bytes) largest = &p;
  }
  if (needed <= machine.usable()) return "";
  std::string text = "the run would need about " + gb(needed) + " of memory";
  if (largest != nullptr) text += ", " + gb(largest->bytes) + " of it for " + largest->name;
  return text + "; this machine has " + machine.describe() + ": " + advice;
}

void reset_peak_memory() {
  std::ofstream clear("/proc/self/clear_refs");
  if (clear) clear << "5";  // 5: reset the peak resident set size
}

double peak_memory_bytes() {
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmHWM:", 0) == 0) {
      std::istringstream fields(line.substr(6));
      double kilobytes = 0;
      fields >> kilobytes;
      return kilobytes * 1024;
    }
  return 0.0;
}

}  // namespace mortar
