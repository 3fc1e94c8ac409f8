#include <gtest/gtest.h>

#include "common/contact/bilateral_contact.hpp"

using namespace mortar;

namespace {
TwoBodies small_bodies(double jitter, double E1 = 1, double E2 = 3) {
  TwoBodyGeometry g;
  g.n1 = 9;
  g.m1 = 4;
  g.n2 = 14;
  g.m2 = 6;
  g.jitter = jitter;
  return make_two_bodies(g, Material(E1, 0.3), Material(E2, 0.25));
}
}  // namespace

TEST(SaddlePoint, lu_and_elimination_give_the_same_solution) {
  const TwoBodies b = small_bodies(0.3);
  const ManufacturedContact exact(b.body(0).material, b.body(1).material, 1.0);
  const SceneData scene = manufactured_scene(b, exact);
  for (Matching m : {Matching::pointwise, Matching::integral})
    for (int nonmortar : {0, 1}) {
      BilateralOptions lu{m, nonmortar, SaddleSolver::lu, fastest_spd_backend()};
      BilateralOptions el{m, nonmortar, SaddleSolver::elimination, fastest_spd_backend()};
      const BilateralSolution a = solve_bilateral(b, scene, lu), c = solve_bilateral(b, scene, el);
      EXPECT_LT((a.u - c.u).norm(), 1e-10 * a.u.norm()) << matching_name(m) << ", non-mortar " << nonmortar;
      EXPECT_LT((a.lambda - c.lambda).norm(), 1e-8 * a.lambda.norm()) << matching_name(m);
      // the constraints hold: B u = 0
      EXPECT_LT((c.constraints.B * c.u).cwiseAbs().maxCoeff(), 1e-14);
      // the multipliers first, through S = B K^{-1} B^T, on either backend
      for (SpdBackend backend : {SpdBackend::simplicial_ldlt, fastest_spd_backend()}) {
        const BilateralSolution d = solve_bilateral(b, scene, {m, nonmortar, SaddleSolver::schur, backend});
        EXPECT_LT((a.u - d.u).norm(), 1e-10 * a.u.norm()) << "schur, " << matching_name(m) << ", " << backend_name(backend);
        EXPECT_LT((a.lambda - d.lambda).norm(), 1e-8 * a.lambda.norm()) << "schur, " << matching_name(m);
        EXPECT_LT((d.constraints.B * d.u).cwiseAbs().maxCoeff(), 1e-12 * d.u.cwiseAbs().maxCoeff());
      }
    }
}

TEST(SaddlePoint, elimination_holds_a_body_that_only_the_constraints_hold) {
  // In the patch test body 1 is free in y: K alone is singular, T^T K T is not.
  const TwoBodies b = small_bodies(0.2);
  const SceneData scene = patch_test_scene(b, 0.01);
  const BilateralSolution s =
      solve_bilateral(b, scene, {Matching::integral, 0, SaddleSolver::elimination, fastest_spd_backend()});
  EXPECT_TRUE(s.u.allFinite());
  EXPECT_THROW(two_body_limit(b, scene), std::runtime_error);  // K alone: reported singular
  // so the multipliers-first route, which factorizes K alone, refuses it instead of guessing
  EXPECT_THROW(solve_bilateral(b, scene, {Matching::integral, 0, SaddleSolver::schur, fastest_spd_backend()}),
               std::runtime_error);
}

TEST(SaddlePoint, a_body_free_to_slide_is_reported_by_both_solvers) {
  // The patch test without the rollers on the left: body 1 slides freely along Gamma_c.
  const TwoBodies b = small_bodies(0.0);
  SceneData scene = patch_test_scene(b, 0.01);
  DirichletData kept;
  for (std::size_t k = 0; k < scene.dirichlet.dofs.size(); ++k)
    if (scene.dirichlet.dofs[k] >= b.offset(1)) {  // keep body 2's data only
      kept.dofs.push_back(scene.dirichlet.dofs[k]);
      kept.values.push_back(scene.dirichlet.values[k]);
    }
  scene.dirichlet = kept;
  for (SaddleSolver solver : {SaddleSolver::lu, SaddleSolver::elimination, SaddleSolver::schur})
    EXPECT_THROW(solve_bilateral(b, scene, {Matching::integral, 0, solver, fastest_spd_backend()}),
                 std::runtime_error)
        << saddle_solver_name(solver);
}

TEST(SaddlePoint, lu_solves_a_stiffness_ratio_of_1e7_as_elimination_does) {
  // With E1 = 1e7 the entries of K reach 1e7 while the patch test's load is 0.01: the residual
  // of a backward-stable solve is of the size eps ||A|| ||x||, far above eps ||b||. Judging it
  // against ||b|| alone called this regular system singular.
  for (double jitter : {0.0, 0.2}) {
    const TwoBodies b = small_bodies(jitter, 1e7, 1);
    const SceneData scene = patch_test_scene(b, 0.01);
    for (Matching m : {Matching::pointwise, Matching::integral}) {
      const BilateralSolution c =
          solve_bilateral(b, scene, {m, 0, SaddleSolver::elimination, fastest_spd_backend()});
      BilateralSolution a;
      ASSERT_NO_THROW(a = solve_bilateral(b, scene, {m, 0, SaddleSolver::lu, fastest_spd_backend()}))
          << matching_name(m) << ", jitter " << jitter;
      // Both solves are backward stable; their answers differ by up to cond(K) eps, about
      // 1e7 (the stiffness ratio) x 1e3 (the mesh) x 1e-16 = 1e-6 (measured: 1.5e-9).
      EXPECT_LT((a.u - c.u).norm(), 1e-6 * c.u.norm()) << matching_name(m);
      EXPECT_LT((a.lambda - c.lambda).norm(), 1e-6 * c.lambda.norm()) << matching_name(m);
    }
  }
}
