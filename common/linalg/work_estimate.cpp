#include "common/linalg/work_estimate.hpp"

#include <Eigen/Dense>
#include <chrono>
#include <cstdio>
#include <stdexcept>

namespace mortar {

double dense_block_flops(const std::string& solver, double m, double t) {
  const double nc = m + t;
  if (solver == "schur") return nc * nc * nc / 3 + nc * nc * m + nc * m * m + m * m * m / 3;
  if (solver == "elimination") return 14 * m * t + 2 * t * t * m + t * t * t / 3;
  if (solver == "lu") return 2 * nc * nc * nc / 3;
  throw std::invalid_argument("dense_block_flops: unknown solver '" + solver + "' (schur, elimination or lu)");
}

double measured_dense_flop_rate() {
  // products of 384 x 384 matrices (2 * 384^3 = 1.1e8 operations each) until 0.1 s has passed
  const int n = 384;
  const Eigen::MatrixXd A = Eigen::MatrixXd::Random(n, n), B = Eigen::MatrixXd::Random(n, n);
  Eigen::MatrixXd C(n, n);
  const auto start = std::chrono::steady_clock::now();
  double seconds = 0;
  int products = 0;
  do {
    C.noalias() = A * B;
    ++products;
    seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  } while (seconds < 0.1);
  return 2.0 * n * n * n * products / seconds;
}

std::string long_run_warning(double flops, const std::string& what, double seconds_worth_warning) {
  constexpr double worth_measuring = 1e10;  // a second or more on this machine: 0.1 s to measure is nothing beside it
  if (flops < worth_measuring) return "";
  const double rate = measured_dense_flop_rate();
  const double seconds = flops / rate;
  if (seconds < seconds_worth_warning) return "";
  char message[512];
  std::snprintf(message, sizeof message,
                "warning: %s need about %.2g floating-point operations: about %.0f s at the %.2g operations per "
                "second this machine does now, most of the run",
                what.c_str(), flops, seconds, rate);
  return message;
}

}  // namespace mortar
