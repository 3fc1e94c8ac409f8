#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

#include "common/contact/contact_scenes.hpp"
#include "common/contact/two_bodies.hpp"
#include "common/fem/dirichlet.hpp"
#include "common/linalg/spd_solver.hpp"

using namespace mortar;

namespace {
ReducedSystem clamped_block(int n) {
  RectangleSpec s;
  s.nx = n; s.ny = n; s.jitter = 0.2;
  const Mesh mesh = rectangle_mesh(s);
  DirichletData data;
  prescribe_on_sides(data, mesh, {Side::bottom}, [](const Eigen::Vector2d&) { return Eigen::Vector2d(0, 0); });
  Eigen::VectorXd F = Eigen::VectorXd::Zero(mesh.num_dofs());
  add_traction(F, mesh, Side::top, [](const Eigen::Vector2d& p) { return Eigen::Vector2d(0.1, -1 - p.x()); }, 2);
  return eliminate_dirichlet(assemble_stiffness(mesh, Material(1, 0.3)), F, data);
}
}  // namespace

TEST(SpdSolver, cholmod_and_simplicial_ldlt_agree) {
  if (!cholmod_available()) GTEST_SKIP() << "this build has no CHOLMOD; the fallback is tested below";
  const ReducedSystem r = clamped_block(40);
  SpdSolver fast(SpdBackend::cholmod), readable(SpdBackend::simplicial_ldlt);
  fast.factorize(r.K);
  readable.factorize(r.K);
  const Eigen::VectorXd a = fast.solve(r.rhs), b = readable.solve(r.rhs);
  EXPECT_LT((a - b).norm(), 1e-10 * a.norm());
}

TEST(SpdSolver, every_backend_solves_to_small_residual_and_reuses_its_factorization) {
  const ReducedSystem r = clamped_block(30);
  for (SpdBackend b : {SpdBackend::simplicial_ldlt, SpdBackend::cholmod}) {
    if (b == SpdBackend::cholmod && !cholmod_available()) continue;
    SpdSolver solver(b);
    solver.factorize(r.K);
    for (int k = 0; k < 3; ++k) {
      const Eigen::VectorXd rhs = r.rhs * (k + 1) + Eigen::VectorXd::Constant(r.rhs.size(), 0.01 * k);
      const Eigen::VectorXd x = solver.solve(rhs);
      EXPECT_LT((r.K * x - rhs).norm(), 1e-10 * rhs.norm()) << backend_name(b) << ", rhs " << k;
    }
  }
}

TEST(SpdSolver, a_floating_body_is_reported_not_solved) {
  // No Dirichlet data: K has three rigid-body modes and is only semidefinite.
  RectangleSpec s;
  s.nx = 6; s.ny = 6;
  const Mesh mesh = rectangle_mesh(s);
  const SparseMatrix K = assemble_stiffness(mesh, Material(1, 0.3));
  for (SpdBackend b : {SpdBackend::simplicial_ldlt, SpdBackend::cholmod}) {
    if (b == SpdBackend::cholmod && !cholmod_available()) continue;
    SpdSolver solver(b);
    EXPECT_THROW(solver.factorize(K), std::runtime_error) << backend_name(b);
  }
}

TEST(SpdSolver, solve_before_factorize_is_an_error) {
  SpdSolver solver(SpdBackend::simplicial_ldlt);
  EXPECT_THROW(solver.solve(Eigen::VectorXd::Ones(3)), std::logic_error);
}

TEST(SpdSolver, a_body_free_to_slide_is_reported_by_every_backend) {
  // Rollers on the left side (u_x = 0) and nothing else: the body can still translate in y.
  RectangleSpec s;
  s.nx = 12; s.ny = 6; s.jitter = 0.2;
  const Mesh mesh = rectangle_mesh(s);
  DirichletData data;
  for (int a : mesh.nodes_on(Side::left)) {
    data.dofs.push_back(2 * a);
    data.values.push_back(0.0);
  }
  const ReducedSystem r = eliminate_dirichlet(assemble_stiffness(mesh, Material(1, 0.3)),
                                              Eigen::VectorXd::Zero(mesh.num_dofs()), data);
  for (SpdBackend b : {SpdBackend::simplicial_ldlt, SpdBackend::cholmod}) {
    if (b == SpdBackend::cholmod && !cholmod_available()) continue;
    SpdSolver solver(b);
    try {
      solver.factorize(r.K);
      ADD_FAILURE() << backend_name(b) << " factorized a singular K without complaint";
    } catch (const std::runtime_error& e) {
      EXPECT_NE(std::string(e.what()).find("free to move rigidly"), std::string::npos) << e.what();
    }
  }
}

TEST(SpdSolver, a_stiffness_ratio_of_1e12_is_not_mistaken_for_singularity) {
  // Two clamped blocks, E = 1e6 and 1e-6, in one block-diagonal matrix.
  const ReducedSystem stiff = clamped_block(24);
  SparseMatrix K(2 * stiff.K.rows(), 2 * stiff.K.rows());
  std::vector<Eigen::Triplet<double>> t;
  for (int k = 0; k < stiff.K.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(stiff.K, k); it; ++it) {
      t.emplace_back(it.row(), it.col(), 1e6 * it.value());
      t.emplace_back(it.row() + stiff.K.rows(), it.col() + stiff.K.rows(), 1e-6 * it.value());
    }
  K.setFromTriplets(t.begin(), t.end());
  for (SpdBackend b : {SpdBackend::simplicial_ldlt, SpdBackend::cholmod}) {
    if (b == SpdBackend::cholmod && !cholmod_available()) continue;
    SpdSolver solver(b);
    EXPECT_NO_THROW(solver.factorize(K)) << backend_name(b);
    const Eigen::VectorXd rhs = Eigen::VectorXd::Ones(K.rows());
    const Eigen::VectorXd x = solver.solve(rhs);
    EXPECT_LT((K * x - rhs).norm(), 1e-8 * rhs.norm()) << backend_name(b);
  }
}

namespace {
// The 7-point Laplacian of an n x n x n grid with Dirichlet boundary: SPD, and unlike the 2D
// meshes here (where CHOLMOD keeps AMD anyway) costly enough under AMD that CHOLMOD's own
// choice is METIS (n = 25: METIS's factor has 1.9e6 nonzeros, AMD's 2.4e6).
SparseMatrix laplacian_3d(int n) {
  const auto id = [n](int i, int j, int k) { return (k * n + j) * n + i; };
  std::vector<Eigen::Triplet<double>> t;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const int a = id(i, j, k);
        t.emplace_back(a, a, 6.0);
        for (int b : {i + 1 < n ? id(i + 1, j, k) : -1, j + 1 < n ? id(i, j + 1, k) : -1,
                      k + 1 < n ? id(i, j, k + 1) : -1})
          if (b >= 0) {
            t.emplace_back(a, b, -1.0);
            t.emplace_back(b, a, -1.0);
          }
      }
  SparseMatrix K(n * n * n, n * n * n);
  K.setFromTriplets(t.begin(), t.end());
  return K;
}
}  // namespace

// factorize(K) orders by AMD alone (no METIS or nested dissection), SpdOrdering::automatic
// lets CHOLMOD search: a different factor of the same K, so the same solution to rounding.
TEST(SpdSolver, amd_ordering_gives_the_automatic_solution) {
  if (!cholmod_available()) GTEST_SKIP() << "the ordering is CHOLMOD's";
  const SparseMatrix K = laplacian_3d(25);
  const Eigen::VectorXd rhs = Eigen::VectorXd::LinSpaced(K.rows(), -1, 2);
  SpdSolver automatic(SpdBackend::cholmod), amd(SpdBackend::cholmod);
  automatic.factorize(K, SpdOrdering::automatic);
  amd.factorize(K);
  EXPECT_EQ(amd.ordering_used(), "amd");
  EXPECT_NE(automatic.ordering_used(), "amd") << "on this 3D grid CHOLMOD's search keeps METIS or nested dissection";
  const Eigen::VectorXd a = automatic.solve(rhs), b = amd.solve(rhs);
  EXPECT_LT((a - b).norm(), 1e-12 * a.norm()) << "CHOLMOD's own choice: " << automatic.ordering_used();
  EXPECT_LT((K * b - rhs).norm(), 1e-10 * rhs.norm());
}

namespace {
// Two bodies held by the plates of pressed_between_plates, Dirichlet dofs eliminated: K is
// block diagonal (the bodies are not coupled), as in the contact solvers.
struct ClampedPair {
  TwoBodies bodies;
  ReducedSystem system;
};
ClampedPair two_clamped_bodies() {
  TwoBodyGeometry g;
  g.n1 = 10; g.m1 = 5; g.n2 = 7; g.m2 = 4; g.jitter = 0.2;
  TwoBodies bodies = make_two_bodies(g, Material(1, 0.3), Material(20, 0.25));
  const SceneData scene = pressed_between_plates(bodies, 0.02);
  ReducedSystem system = eliminate_dirichlet(bodies.stiffness(), scene.F, scene.dirichlet);
  return {std::move(bodies), std::move(system)};
}

// The free unknowns of both bodies' nodes on Gamma_c (both components): the contact line.
std::vector<int> contact_line_unknowns(const ClampedPair& p) {
  std::vector<int> c;
  for (int l : {0, 1})
    for (int a : p.bodies.body(l).mesh.nodes_on(l == 0 ? Side::bottom : Side::top))
      for (int k : {0, 1})
        if (const int f = p.system.full_to_free[p.bodies.dof(l, a, k)]; f >= 0) c.push_back(f);
  return c;
}

// (K^{-1})_cc, column by column, from solves with unit vectors by an independent
// SimplicialLDLT factorization.
Eigen::MatrixXd inverse_block(const SparseMatrix& K, const std::vector<int>& c) {
  SpdSolver reference(SpdBackend::simplicial_ldlt);
  reference.factorize(K);
  const int m = static_cast<int>(c.size());
  Eigen::MatrixXd block(m, m);
  for (int j = 0; j < m; ++j) {
    Eigen::VectorXd e = Eigen::VectorXd::Zero(K.rows());
    e[c[j]] = 1;
    const Eigen::VectorXd x = reference.solve(e);
    for (int i = 0; i < m; ++i) block(i, j) = x[c[i]];
  }
  return block;
}
}  // namespace

// With the unknowns `last` ordered last, the trailing block L_c of the factor is the Cholesky
// factor of the Schur complement on them: L_c^{-T} L_c^{-1} = (K^{-1})_cc in the order
// t.dofs, which must hold exactly the unknowns `last`. This is what the contact solvers build
// S = B K^{-1} B^T from, so a wrong entry, a wrong order or a missing unknown changes S.
// Two sets: the contact line (both bodies) and a few scattered unknowns given unsorted.
TEST(SpdSolver, trailing_factor_is_the_inverse_on_the_last_unknowns) {
  if (!cholmod_available()) GTEST_SKIP() << "factorize_with_last needs CHOLMOD";
  const ClampedPair pair = two_clamped_bodies();
  const ReducedSystem& r = pair.system;
  const int n = static_cast<int>(r.K.rows());
  const std::vector<int> line = contact_line_unknowns(pair);
  ASSERT_GT(line.size(), 20u);
  std::vector<int> every(static_cast<std::size_t>(n));  // nothing left for AMD to order
  std::iota(every.begin(), every.end(), 0);
  ASSERT_LT(n, 3000) << "keep the dense check small";
  for (const std::vector<int>& last : {line, std::vector<int>{n / 2, 3, n - 1, 0, n / 3, 17}, every}) {
    SpdSolver solver(SpdBackend::cholmod);
    solver.factorize_with_last(r.K, last);
    const SpdSolver::TrailingFactor t = solver.trailing_factor();
    std::vector<int> got = t.dofs, want = last;
    std::sort(got.begin(), got.end());
    std::sort(want.begin(), want.end());
    ASSERT_EQ(got, want) << "t.dofs is not a permutation of last";
    ASSERT_EQ(t.L.rows(), static_cast<Eigen::Index>(last.size()));
    ASSERT_EQ(t.L.cols(), static_cast<Eigen::Index>(last.size()));
    EXPECT_EQ(Eigen::MatrixXd(t.L.triangularView<Eigen::StrictlyUpper>()).cwiseAbs().maxCoeff(), 0.0);
    const Eigen::MatrixXd L_inv =
        t.L.triangularView<Eigen::Lower>().solve(Eigen::MatrixXd::Identity(t.L.rows(), t.L.cols()));
    const Eigen::MatrixXd from_factor = L_inv.transpose() * L_inv;
    const Eigen::MatrixXd from_solves = inverse_block(r.K, t.dofs);
    EXPECT_LT((from_factor - from_solves).norm(), 1e-10 * from_solves.norm()) << last.size() << " unknowns last";
    // and the factor still solves K x = b
    const Eigen::VectorXd b = Eigen::VectorXd::LinSpaced(n, -1, 2);
    const Eigen::VectorXd x = solver.solve(b);
    EXPECT_LT((r.K * x - b).norm(), 1e-10 * b.norm());
  }
}

// trailing_factor() reads a factor ordered by factorize_with_last: before any factorization,
// or after a plain factorize (even one that follows factorize_with_last), there is none, and
// the error says so (a set left over from the earlier call is not read in the new factor).
TEST(SpdSolver, trailing_factor_without_factorize_with_last_is_an_error) {
  if (!cholmod_available()) GTEST_SKIP() << "factorize_with_last needs CHOLMOD";
  const ClampedPair pair = two_clamped_bodies();
  const SparseMatrix& K = pair.system.K;
  SpdSolver solver(SpdBackend::cholmod);
  const auto expect_refusal = [&solver](const std::string& when) {
    try {
      solver.trailing_factor();
      ADD_FAILURE() << when << ": no error";
    } catch (const std::logic_error& e) {
      EXPECT_NE(std::string(e.what()).find("without factorize_with_last"), std::string::npos) << when << ": " << e.what();
    }
  };
  expect_refusal("before any factorization");
  solver.factorize(K);
  expect_refusal("after factorize");
  solver.factorize_with_last(K, contact_line_unknowns(pair));
  EXPECT_NO_THROW(solver.trailing_factor());
  solver.factorize(K);
  expect_refusal("after factorize_with_last, then factorize");
}

namespace {
double address_space_in_use() {
  std::ifstream status("/proc/self/status");
  std::string key;
  double kb = 0;
  while (status >> key)
    if (key == "VmSize:" && status >> kb) return kb * 1024;
  return 0;
}
}  // namespace

// CHOLMOD reports running out of memory only in cholmod_common::status; Eigen's info() does
// not look there. In a child process with an address-space limit just above what it already
// uses, the factorization of a 130k-dof K must end in a runtime_error saying "out of memory",
// not in a crash on the missing factor, and within the alarm (no endless retry).
TEST(SpdSolver, cholmod_out_of_memory_is_an_error_not_a_crash) {
  if (!cholmod_available()) GTEST_SKIP() << "this build has no CHOLMOD";
#if defined(__SANITIZE_ADDRESS__)
  // AddressSanitizer reserves terabytes of address space for its shadow memory: a limit on
  // the address space cannot stand for a machine running out of memory there.
  GTEST_SKIP() << "an address-space limit means nothing under AddressSanitizer";
#endif
  const ReducedSystem small = clamped_block(20), large = clamped_block(256);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    alarm(60);
    SpdSolver warm(SpdBackend::cholmod);
    warm.factorize(small.K);  // maps OpenBLAS's buffers while memory is still there
    SpdSolver solver(SpdBackend::cholmod);
    const rlimit limit{static_cast<rlim_t>(address_space_in_use() + 40e6), RLIM_INFINITY};
    setrlimit(RLIMIT_AS, &limit);
    try {
      solver.factorize(large.K);
    } catch (const std::runtime_error& e) {
      const bool says_so = std::string(e.what()).find("out of memory") != std::string::npos;
      if (!says_so) std::fprintf(stderr, "%s\n", e.what());
      _exit(says_so ? 0 : 3);
    } catch (const std::bad_alloc&) {
      _exit(4);
    }
    _exit(5);  // the factorization fitted: the limit was not tight enough
  }
  int status = 0;
  waitpid(child, &status, 0);
  ASSERT_TRUE(WIFEXITED(status)) << "the child died of signal " << (WIFSIGNALED(status) ? WTERMSIG(status) : 0);
  EXPECT_EQ(WEXITSTATUS(status), 0) << "3: another message, 4: std::bad_alloc, 5: no failure";
}
