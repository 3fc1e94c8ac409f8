// Part 2 of chapter 6: unilateral contact on chapter 5's Hertz scene, with the standard basis
// of M_h^1 (chapter 5's primal-dual active set on S = B K^{-1} B^T) and with the dual basis
// (the weighted gap and the semismooth Newton method in the displacements), on the same meshes.
#pragma once

#include <string>
#include <vector>

#include "common/study/active_sets.hpp"
#include "common/contact/contact_fields.hpp"
#include "common/interface/dual_basis.hpp"
#include "common/linalg/physical_limit.hpp"
#include "common/study/bilateral_study.hpp"

namespace chapter06 {

// Chapter 5's Hertz scene: top of body 1 moved by (0, -delta), bottom of body 2 clamped,
// gap (x - L/2)^2 / (2R); its bodies (square blocks, one material) unless given otherwise.
struct HertzOptions {
  mortar::TwoBodyOptions bodies;
  int n0 = 12, levels = 5;
  double R = 1, delta = 0.02;
  bool nested_start = true;  // dual: each level's first active set from the level below
};

// The memory of part 2's finest level on the options of part 1: square blocks L tall, so
// (n + 1)^2 nodes a body whatever --H1, --H2 and --aspect say; the standard basis builds S
// and the factor's dense block on Gamma_c (memory_estimate.hpp).
std::vector<mortar::MemoryPart> hertz_memory_parts(const mortar::BilateralStudyOptions& o);

enum class Basis { standard, dual };
std::string basis_name(Basis basis);

struct HertzLevel {
  Basis basis = Basis::standard;
  int level = 0, dofs = 0, multipliers = 0;
  double h1 = 0;
  double total_force = 0, max_pressure = 0, half_width = 0;
  int iterations = 0;      // standard: active-set steps on S; dual: Newton steps (one factorization each)
  std::vector<int> active_sizes;  // dual: |A| before each Newton step
  mortar::ActiveSetHistory active_sets;  // both: the active rows of each step, at their nodes' x
  double residual = 0;     // complementarity residual
  double min_function = 0; // min of sum_i lambda_i psi_i on Gamma_c (negative: the dual basis)
  mortar::TimedLevel timing;
  mortar::InterfaceCurve pressure;  // coefficients at their nodes
  mortar::BrokenCurve function;     // sum_i lambda_i psi_i
  mortar::ContactZone zone;         // read off the coefficients (contact_fields.hpp)
  // dual rows: ||p_dual - p_standard||_{L2} / ||p_standard||_{L2}, both the P1 curves of the
  // coefficients at the nodes, on the same level (bounds how far the two bases' errors against
  // any reference can differ)
  double pressure_difference = 0;
};

// One level with one basis; `coarser` (may be null) gives the dual Newton method its first
// active set: the rows whose node lies inside the coarser level's contact zone.
HertzLevel solve_hertz_level(const HertzOptions& o, int level, Basis basis, const HertzLevel* coarser);

struct HertzStudy {
  std::vector<HertzLevel> standard, dual;
};
HertzStudy run_hertz_study(const HertzOptions& o);

// hertz.csv: one row per level and basis.
void write_hertz_csv(const std::string& path, const HertzStudy& study);

}  // namespace chapter06
