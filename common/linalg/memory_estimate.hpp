// The memory a run needs against the memory the machine has, checked before any work, so that
// a run the machine cannot hold is refused at once instead of failing after minutes (or, under
// an address-space limit, spinning inside OpenBLAS's allocator, which retries a failed mmap for
// ever).
#pragma once

#include <string>
#include <vector>

namespace mortar {

// Peak bytes per dof of a whole run (assembly, sparse Cholesky factor, errors, output),
// measured with `/usr/bin/time -v` ("Maximum resident set size") on the finest level:
//   ch02_p1_triangles   132,098 dofs 0.35 GB, 526,338 dofs 1.31 GB, 2,101,250 dofs 5.69 GB
//                       (2.5-2.7 kB/dof; the factor's fill grows like n log n);
//   ch04_integral_matching 214,916 dofs 0.50 GB, 855,812 dofs 1.99 GB (2.3 kB/dof).
// 3 kB/dof covers both with a margin of about 10 %.
constexpr double bytes_per_dof_single_solve = 3000;

// What a run needs: a fixed part (libraries, thread stacks, and the 128 MB buffers OpenBLAS
// maps per thread; a run of 8,450 dofs needed 330-360 MB of address space on 2 hardware
// threads) plus bytes_per_dof for each dof of the finest level.
double run_bytes(double dofs, double bytes_per_dof);

// The memory a run may use: MemAvailable of /proc/meminfo and the soft RLIMIT_AS
// (`ulimit -v`), each infinite when unknown or unlimited.
struct MachineMemory {
  double available_bytes;
  double address_limit_bytes;
  double usable() const;        // the smaller of the two
  std::string describe() const;  // e.g. "23.9 GB available, address space limited to 0.5 GB"
};
MachineMemory machine_memory();
// MemAvailable from the text of /proc/meminfo; infinite when the line is missing.
double mem_available_bytes(const std::string& meminfo);

// "" when a run of `dofs` finest-level dofs fits, else a sentence naming the dofs, the memory
// they need and what the machine has (for OptionParser::fail).
std::string memory_shortfall(double dofs, double bytes_per_dof, const MachineMemory& machine);

// A run in parts, for runs whose memory is not all in the finest level's sparse solve: each
// part named (e.g. "S = B K^-1 B^T, 4095 x 4095, dense"), its bytes counted before any work.
struct MemoryPart {
  std::string name;
  double bytes = 0;
};
// The bytes of a dense rows x cols matrix of doubles.
double dense_bytes(double rows, double cols);

// The dense blocks one saddle-point or contact solve builds on Gamma_c, for m constraint rows
// that touch t unknowns besides their own pivots (the mortar side's):
//  - "schur" (S = B K^-1 B^T from CHOLMOD's trailing factor): the trailing block of the factor,
//    dense on the n_c = m + t touched unknowns, and its copy; W = L_cc^-1 B_c^T (n_c x m); S;
//  - "elimination": B_r on the touched columns and X = -B_s^-1 B_r (m x t, each also as
//    triplets and a sparse matrix), and the t x t block X^T K_ss X added to K with its factor.
// Upper bounds, measured as the largest resident set of whole runs of ch04 on bodies one cell
// thick (m = 4095, t = 2732): schur 1.10 GB against 1.10 GB counted here for its dense blocks
// alone, elimination 0.98 GB against 0.97 GB.
double schur_dense_bytes(double m, double t);
double elimination_dense_bytes(double m, double t);

// "" when the fixed part and every part fit, else a sentence naming the largest part, its
// size, the whole and what the machine has, ending with `advice`.
std::string memory_shortfall(const std::vector<MemoryPart>& parts, const MachineMemory& machine,
                             const std::string& advice = "use fewer --levels or a smaller --n0");

// The resident-set peak of this process (VmHWM of /proc/self/status), and setting it back to
// the present resident set (Linux's /proc/self/clear_refs), so that the peak of one step can
// be read. 0 where the system does not say.
void reset_peak_memory();
double peak_memory_bytes();

}  // namespace mortar
