// Sparse symmetric positive definite solves: CHOLMOD supernodal Cholesky over OpenBLAS when
// available (the fast path), Eigen's SimplicialLDLT otherwise (the readable fallback).
// One factorization serves any number of right-hand sides.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "common/fem/p1_elasticity.hpp"

namespace mortar {

enum class SpdBackend { cholmod, simplicial_ldlt };

// The fill-reducing ordering of CHOLMOD's analysis:
//  - amd (the default, for every program and for the physical limit): AMD only, chosen once;
//  - automatic: CHOLMOD's own choice: AMD, and METIS and nested dissection as well whenever
//    AMD's factor looks costly, keeping the best. On the course's 2D meshes that search costs
//    more than it saves: at 1.71M dofs (chapter 5, --levels 7) 8.7 s of analysis buy a
//    factorization of 15.1 s instead of AMD's 17.4 s (after 1.4 s of analysis).
enum class SpdOrdering { automatic, amd };

bool cholmod_available();
SpdBackend fastest_spd_backend();  // CHOLMOD when built in, else SimplicialLDLT
std::string backend_name(SpdBackend backend);

// Threads of the dense kernels under CHOLMOD (OpenBLAS's and OpenMP's), for the whole process.
// Returns false when neither library is loaded (then nothing changed).
bool set_solver_threads(int threads);
// The --threads option of every program, and its default: every core. Measured both ways on
// the 2-core build machine (README.md, "Speed"): the second thread makes CHOLMOD's
// factorization about a third faster from 100k dofs up, so it is kept although it lifts the
// ratio to the limit (the rest of a level does not speed up with it).
int default_solver_threads();
constexpr const char* solver_threads_help =
    "threads of the dense kernels under CHOLMOD (OpenBLAS, OpenMP); the limit runs with the same";

class SpdSolver {
 public:
  explicit SpdSolver(SpdBackend backend = fastest_spd_backend());
  ~SpdSolver();
  SpdSolver(SpdSolver&&) noexcept;
  SpdSolver& operator=(SpdSolver&&) noexcept;

  // Factorizes K (lower triangle is read). Throws std::runtime_error naming the problem when
  // K is not positive definite, e.g. a body left free to move rigidly.
  void factorize(const SparseMatrix& K, SpdOrdering ordering = SpdOrdering::amd);
  // The same with the unknowns `last` ordered after all others (CHOLMOD only): AMD orders the
  // rest, `last` is appended. Then the trailing block of the factor is the Cholesky factor of
  // the Schur complement of K on `last`; trailing_factor() returns it.
  void factorize_with_last(const SparseMatrix& K, const std::vector<int>& last);

  // A matrix with the pattern of the last one factorized (explicit zeros included): the
  // analysis is kept, only the numerical factorization runs (chapter 6's Newton steps).
  void refactorize(const SparseMatrix& K);

  // After factorize_with_last: the dense lower-triangular L_c with
  //     (K^{-1})_{cc} = L_c^{-T} L_c^{-1},   c = dofs (the unknowns `last`, in the factor's order),
  // read off the factor: no solve. |c| x |c| doubles, the size of the contact line, not the mesh.
  struct TrailingFactor {
    std::vector<int> dofs;
    Eigen::MatrixXd L;
  };
  TrailingFactor trailing_factor() const;
  // The ordering the analysis kept ("amd", "metis", "nesdis", "given", ...).
  std::string ordering_used() const;
  Eigen::VectorXd solve(const Eigen::VectorXd& rhs) const;
  // Several right-hand sides at once (the columns of rhs): one pass through the factor.
  Eigen::MatrixXd solve_many(const Eigen::MatrixXd& rhs) const;
  SpdBackend backend() const { return backend_; }

 private:
  void factorize(const SparseMatrix& K, SpdOrdering ordering, std::vector<int> given);
  // AMD's order of the unknowns not in `last`, from K restricted to them.
  void check_ldlt(const Eigen::VectorXd& diagonal) const;
  void check_cholmod(const Eigen::VectorXd& diagonal) const;
  std::vector<int> amd_order_of_rest(const SparseMatrix& K, const std::vector<int>& last);
  struct Impl;
  SpdBackend backend_;
  std::unique_ptr<Impl> impl_;
};

}  // namespace mortar
