// The time a run will take where it is not in the sparse solve, estimated before any work, as
// memory_estimate.hpp does for memory. On bodies a few cells thick along a long Gamma_c the
// sparse factor of K is cheap and the dense blocks on Gamma_c (dense in the m multipliers and
// the t mortar nodes they touch) cost O((m + t)^3): thousands of times the physical limit,
// minutes where a user expects seconds. A run that long is announced, not refused.
#pragma once

#include <string>

namespace mortar {

// Floating-point operations of the dense blocks of one saddle-point solve on Gamma_c, for m
// constraint rows touching t unknowns besides their own pivots (memory_estimate.hpp):
//  - "schur": the trailing block of K's factor, dense on n_c = m + t unknowns (n_c^3 / 3),
//    W = L_cc^-1 B_c^T (n_c^2 m), S = W^T W (n_c m^2) and its Cholesky factor (m^3 / 3);
//  - "elimination": X = -B_s^-1 B_r (B_s banded: about 4 m t), X^T K_ss X (about 10 m t + 2 t^2 m)
//    and the dense t x t block in K's factor (t^3 / 3);
//  - "lu": one LU of the saddle-point matrix, dense on the n_c unknowns of Gamma_c (2 n_c^3 / 3).
double dense_block_flops(const std::string& solver, double m, double t);

// Dense floating-point operations per second of this machine now, measured by a matrix
// product of about 0.1 s (Eigen's, which runs on the cores the solves use).
double measured_dense_flop_rate();

// "" when the dense blocks of every level (flops, summed by the caller) take less than
// `seconds_worth_warning` at the measured rate, else a sentence: the estimated time and what it
// is spent on. The rate is measured only beyond 1e10 operations (a second or more here), so
// small runs pay nothing. Measured against the model: ch04 on bodies one cell thick
// (--H1 --H2 0.000244140625, schur), n0 = 512: 5.4e10 operations, 13.6 s at 4e9 per second.
std::string long_run_warning(double flops, const std::string& what, double seconds_worth_warning = 30);

}  // namespace mortar
