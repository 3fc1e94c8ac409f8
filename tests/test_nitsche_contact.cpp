#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>

#include "common/contact/contact_scenes.hpp"
#include "common/contact/hertz_half_planes.hpp"
#include "common/contact/nitsche_contact.hpp"
#include "common/contact/nitsche_steps.hpp"
#include "common/fem/dirichlet.hpp"
#include "common/interface/interface_trace.hpp"
#include "common/linalg/spd_solver.hpp"

using namespace mortar;

namespace {

TwoBodies small_bodies(double jitter = 0.2) {
  TwoBodyGeometry g;
  g.n1 = 7; g.m1 = 3; g.n2 = 5; g.m2 = 2; g.jitter = jitter;
  return make_two_bodies(g, Material(1, 0.3), Material(3, 0.25));
}

double parabola(double x) { return (x - 0.5) * (x - 0.5) / 2; }

// Body 1 pushed down by 0.02 with some noise: P_gamma > 0 near x = 0.5, < 0 near the ends.
Eigen::VectorXd pressed_state(const TwoBodies& b, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> noise(-1e-3, 1e-3);
  Eigen::VectorXd u(b.num_dofs());
  for (int i = 0; i < b.num_dofs(); ++i) u[i] = noise(rng);
  for (int a = 0; a < b.body(0).mesh.num_nodes(); ++a) u[b.dof(0, a, 1)] -= 0.02;
  return u;
}

Eigen::VectorXd contact_residual(const std::vector<NitscheSegment>& s, const NitscheOptions& o, const Eigen::VectorXd& u) {
  Eigen::VectorXd r = Eigen::VectorXd::Zero(u.size());
  add_nitsche_terms(s, parabola, o, u, r, nullptr);
  return r;
}

std::vector<NitscheOptions> variants() {
  std::vector<NitscheOptions> v;
  for (double theta : {1.0, 0.0, -1.0})
    for (double w : {1.0, 0.0, 0.5}) {
      NitscheOptions o;
      o.theta = theta;
      o.body1_weight = w;
      o.gamma0 = 3;
      v.push_back(o);
    }
  NitscheOptions penalty;
  penalty.penalty = true;
  v.push_back(penalty);
  return v;
}

// The triangle of a mesh that holds the point, by barycentric coordinates.
int triangle_at(const Mesh& mesh, const Eigen::Vector2d& p) {
  for (int t = 0; t < static_cast<int>(mesh.triangles.size()); ++t) {
    const auto x = triangle_vertices(mesh, t);
    Eigen::Matrix2d A;
    A << x[1] - x[0], x[2] - x[0];
    const Eigen::Vector2d l = A.inverse() * (p - x[0]);
    if (l.minCoeff() >= -1e-12 && l.sum() <= 1 + 1e-12) return t;
  }
  return -1;
}

// Chapter 5's exact Hertz scene on 16 and 11 elements: u prescribed on every outer side, so
// K_ff alone is positive definite.
struct SmallHertz {
  Material m{1, 0.3};
  HertzHalfPlanes exact{m, m, 0.5, std::sqrt(2.0) / 6, 1};
  TwoBodies bodies;
  SceneData scene;
  SmallHertz() : bodies(make_two_bodies(geometry(), m, m)), scene(manufactured_scene_all_sides(bodies, exact)) {}
  static TwoBodyGeometry geometry() {
    TwoBodyGeometry g;
    g.n1 = 16; g.m1 = 16; g.n2 = 11; g.m2 = 11; g.H1 = g.H2 = 1;
    return g;
  }
};

}  // namespace

// The segment's functionals against the fields they stand for, computed another way: [u.n] from
// each body's trace (InterfaceTrace::evaluate), p(u) from element_stresses of the triangle that
// holds a point just inside each body.
TEST(NitscheContact, segment_functionals_are_the_jump_and_the_traction) {
  const TwoBodies b = small_bodies();
  const Eigen::VectorXd u = pressed_state(b, 3);
  NitscheOptions o;
  o.body1_weight = 0.3;
  const InterfaceTrace t1 = trace_on_side(b.body(0).mesh, Side::bottom), t2 = trace_on_side(b.body(1).mesh, Side::top);
  std::vector<double> v1, v2;
  for (int node : t1.nodes) v1.push_back(u[b.dof(0, node, 1)]);
  for (int node : t2.nodes) v2.push_back(u[b.dof(1, node, 1)]);
  const auto s1 = element_stresses(b.body(0).mesh, b.body(0).material, b.part(u, 0));
  const auto s2 = element_stresses(b.body(1).mesh, b.body(1).material, b.part(u, 1));
  const std::vector<NitscheSegment> segments = nitsche_segments(b, o);
  ASSERT_GE(segments.size(), 10u);
  for (const NitscheSegment& s : segments) {
    Eigen::Matrix<double, 12, 1> ul;
    for (int i = 0; i < 12; ++i) ul(i) = u[s.dofs[i]];
    for (double x : {s.a, 0.3 * s.a + 0.7 * s.b, s.b})
      EXPECT_NEAR(s.jump(x).dot(ul), t2.evaluate(v2, x) - t1.evaluate(v1, x), 1e-14);
    const double m = 0.5 * (s.a + s.b);
    const int T1 = triangle_at(b.body(0).mesh, {m, 1e-9}), T2 = triangle_at(b.body(1).mesh, {m, -1e-9});
    ASSERT_GE(T1, 0);
    ASSERT_GE(T2, 0);
    EXPECT_NEAR(s.p.dot(ul), -(0.3 * s1[T1][1] + 0.7 * s2[T2][1]), 1e-13);
    const double h1 = t1.x[t1.element_containing(m) + 1] - t1.x[t1.element_containing(m)];
    const double h2 = t2.x[t2.element_containing(m) + 1] - t2.x[t2.element_containing(m)];
    EXPECT_NEAR(s.gamma, 1.0 * (0.3 * 1 / h1 + 0.7 * 3 / h2), 1e-12 * s.gamma);
  }
}

// The residual against a brute-force quadrature of the same integrals: 4000 midpoints per segment
// with [P_gamma]_+ evaluated pointwise, no cutting at the roots (so it converges like n^-2).
TEST(NitscheContact, residual_matches_a_brute_force_quadrature) {
  const TwoBodies b = small_bodies();
  const Eigen::VectorXd u = pressed_state(b, 5);
  for (const NitscheOptions& o : variants()) {
    const std::vector<NitscheSegment> segments = nitsche_segments(b, o);
    const Eigen::VectorXd r = contact_residual(segments, o, u);
    Eigen::VectorXd brute = Eigen::VectorXd::Zero(u.size());
    const double theta = o.penalty ? 0.0 : o.theta;
    int active = 0;
    for (const NitscheSegment& s : segments) {
      Eigen::Matrix<double, 12, 1> ul, p = o.penalty ? Eigen::Matrix<double, 12, 1>::Zero() : s.p;
      for (int i = 0; i < 12; ++i) ul(i) = u[s.dofs[i]];
      const int n = 4000;
      for (int k = 0; k < n; ++k) {
        const double x = s.a + (k + 0.5) * (s.b - s.a) / n, w = (s.b - s.a) / n;
        const double P = p.dot(ul) + s.gamma * (s.jump(x).dot(ul) - parabola(x));
        const Eigen::Matrix<double, 12, 1> local =
            w * (std::max(P, 0.0) * (theta * p + s.gamma * s.jump(x)) - theta * p.dot(ul) * p) / s.gamma;
        for (int i = 0; i < 12; ++i) brute[s.dofs[i]] += local(i);
        active += P > 0;
      }
    }
    EXPECT_GT(active, 0);
    EXPECT_LT(active, 4000 * static_cast<int>(segments.size())) << "some of Gamma_c must be open";
    EXPECT_LT((r - brute).lpNorm<Eigen::Infinity>(), 1e-7 * r.lpNorm<Eigen::Infinity>())
        << "theta " << o.theta << ", w " << o.body1_weight << (o.penalty ? ", penalty" : "");
  }
}

// The Newton matrix is the derivative of the residual: central differences, column by column.
// Symmetric for theta = 1 and penalty, not for theta = 0 or -1.
TEST(NitscheContact, newton_matrix_is_the_derivative_of_the_residual) {
  const TwoBodies b = small_bodies();
  const Eigen::VectorXd u = pressed_state(b, 7);
  for (const NitscheOptions& o : variants()) {
    const std::vector<NitscheSegment> segments = nitsche_segments(b, o);
    std::vector<Eigen::Triplet<double>> t;
    Eigen::VectorXd r = Eigen::VectorXd::Zero(u.size());
    add_nitsche_terms(segments, parabola, o, u, r, &t);
    SparseMatrix J(u.size(), u.size());
    J.setFromTriplets(t.begin(), t.end());
    const Eigen::MatrixXd dense(J);
    const double eps = 1e-7, scale = dense.lpNorm<Eigen::Infinity>();
    double worst = 0;
    for (int j = 0; j < u.size(); ++j) {
      Eigen::VectorXd up = u, um = u;
      up[j] += eps;
      um[j] -= eps;
      const Eigen::VectorXd column = (contact_residual(segments, o, up) - contact_residual(segments, o, um)) / (2 * eps);
      worst = std::max(worst, (column - dense.col(j)).lpNorm<Eigen::Infinity>());
    }
    EXPECT_LT(worst, 1e-6 * scale) << "theta " << o.theta << ", w " << o.body1_weight << (o.penalty ? ", penalty" : "");
    const double asymmetry = (dense - dense.transpose()).lpNorm<Eigen::Infinity>();
    if (o.penalty || o.theta == 1) EXPECT_LT(asymmetry, 1e-12 * scale);
    else EXPECT_GT(asymmetry, 1e-3 * scale);
  }
}

// The patch test: a uniform pressure crosses nonmatching traces (h2 / h1 = 3 / 7) exactly, for every
// variant, every traction weight, and with jittered nodes.
TEST(NitscheContact, patch_test_is_passed_by_every_variant) {
  TwoBodyGeometry g;
  g.n1 = 6; g.n2 = 14; g.m1 = 3; g.m2 = 7; g.jitter = 0.25;
  const TwoBodies b = make_two_bodies(g, Material(2, 0.3), Material(1, 0.2));
  const double p = 0.01;
  const SceneData scene = patch_test_scene(b, p);
  Eigen::VectorXd start = Eigen::VectorXd::Zero(b.num_dofs());
  for (int a = 0; a < b.body(0).mesh.num_nodes(); ++a) start[b.dof(0, a, 1)] = -0.01;
  for (NitscheOptions o : variants()) {
    o.fixed_gamma = o.penalty ? 50 : 0;  // penalty: the same gamma everywhere (jittered h1 varies)
    const NitscheSolution s = solve_nitsche_contact(b, scene, [](double) { return 0.0; }, o, &start);
    ASSERT_TRUE(s.converged);
    EXPECT_LE(s.newton_steps, 3);
    double worst = 0;
    for (int l = 0; l < 2; ++l)
      for (const Eigen::Vector3d& sigma : element_stresses(b.body(l).mesh, b.body(l).material, b.part(s.u, l)))
        worst = std::max({worst, std::fabs(sigma[1] + p) / p, std::fabs(sigma[0]) / p, std::fabs(sigma[2]) / p});
    EXPECT_LT(worst, 1e-11) << "theta " << o.theta << ", w " << o.body1_weight << (o.penalty ? ", penalty" : "");
    // Nitsche leaves no penetration; penalty one of p / gamma
    const auto pressure = nitsche_pressure(nitsche_segments(b, o), [](double) { return 0.0; }, o, s.u);
    EXPECT_NEAR(total_force(pressure), p * g.L, 1e-11);
    const double jump = s.u[b.dof(1, b.body(1).mesh.nodes_on(Side::top)[3], 1)] -
                        s.u[b.dof(0, b.body(0).mesh.nodes_on(Side::bottom)[2], 1)];
    EXPECT_NEAR(jump, o.penalty ? p / 50 : 0.0, 1e-13);
  }
}

TEST(NitscheContact, pressure_pieces_cut_at_the_roots) {
  const TwoBodies b = small_bodies(0);
  NitscheOptions o;
  const Eigen::VectorXd u = pressed_state(b, 11);
  const std::vector<NitscheSegment> segments = nitsche_segments(b, o);
  const auto pieces = nitsche_pressure(segments, parabola, o, u);
  ASSERT_GT(pieces.size(), segments.size()) << "some segment holds a root";
  for (std::size_t k = 0; k + 1 < pieces.size(); ++k) EXPECT_DOUBLE_EQ(pieces[k].b, pieces[k + 1].a);
  std::set<double> segment_ends;
  for (const NitscheSegment& s : segments) segment_ends.insert(s.b);
  int edges = 0, inside = 0;
  for (std::size_t k = 0; k + 1 < pieces.size(); ++k)
    if (pieces[k].active != pieces[k + 1].active) {
      ++edges;
      // a change of the set inside a segment is a root of P_gamma: [P_gamma]_+ is 0 there on
      // both sides (across a segment's end P_gamma may jump with p(u_h))
      if (segment_ends.count(pieces[k].b) == 0) {
        ++inside;
        EXPECT_LT(pieces[k].active ? pieces[k].right : pieces[k + 1].left, 1e-12);
      }
    }
  EXPECT_GE(edges, 2);
  EXPECT_GE(inside, 1);
  EXPECT_GT(contact_half_width(pieces), 0.05);
  EXPECT_LT(contact_half_width(pieces), 0.5);
}

TEST(NitscheContact, harmonic_weight_reads_the_softer_body) {
  EXPECT_DOUBLE_EQ(harmonic_body1_weight(1, 0.1, 1, 0.1), 0.5);
  EXPECT_NEAR(harmonic_body1_weight(1e-6, 0.1, 1, 0.1), 1.0, 1e-5);  // body 1 soft: its traction
  EXPECT_NEAR(harmonic_body1_weight(1e6, 0.1, 1, 0.1), 0.0, 1e-5);
  EXPECT_DOUBLE_EQ(harmonic_body1_weight(1, 0.1, 1, 0.3), 0.25);
}

TEST(NitscheContact, a_start_of_the_wrong_size_is_refused) {
  const TwoBodies b = small_bodies();
  const SceneData scene = patch_test_scene(b, 0.01);
  const Eigen::VectorXd start = Eigen::VectorXd::Zero(3);
  EXPECT_THROW(solve_nitsche_contact(b, scene, parabola, NitscheOptions{}, &start), std::invalid_argument);
}

// The two ways of solving a Newton step (nitsche_steps.hpp) take the same steps to the same
// answer, on chapter 5's exact Hertz scene (u prescribed on every outer side, so K_ff alone is
// positive definite and the condensed way is taken), for every variant.
TEST(NitscheContact, condensed_and_sparse_newton_steps_agree) {
  if (!cholmod_available()) GTEST_SKIP() << "the condensed way needs CHOLMOD's trailing factor";
  const SmallHertz h;
  const TwoBodies& b = h.bodies;
  const SceneData& scene = h.scene;
  for (NitscheOptions o : variants()) {
    o.linear_solver = NitscheLinearSolver::condensed;
    const NitscheSolution condensed = solve_nitsche_contact(b, scene, parabola, o);
    o.linear_solver = NitscheLinearSolver::sparse;
    const NitscheSolution sparse = solve_nitsche_contact(b, scene, parabola, o);
    ASSERT_TRUE(condensed.converged && sparse.converged);
    EXPECT_NE(condensed.solver, sparse.solver);
    EXPECT_EQ(condensed.newton_steps, sparse.newton_steps) << "theta " << o.theta << ", w " << o.body1_weight;
    EXPECT_LT((condensed.u - sparse.u).lpNorm<Eigen::Infinity>(), 1e-12 * sparse.u.lpNorm<Eigen::Infinity>());
    EXPECT_LT(condensed.residual, 1e-12);
  }
}

// theta = 1 far below its coercivity threshold: steps that are not positive definite go to LU,
// then a later positive definite step to Cholesky again (refactorizing after a failed
// factorization was an error); a singular step ends Newton with a reason, never an exception.
TEST(NitscheContact, symmetric_steps_that_lose_positive_definiteness_are_solved_or_reported) {
  const SmallHertz h;
  const TwoBodies& b = h.bodies;
  const SceneData& scene = h.scene;
  for (const NitscheLinearSolver solver : {NitscheLinearSolver::sparse, NitscheLinearSolver::condensed})
    for (const double gamma0 : {1e-3, 0.2, 1.0}) {
      NitscheOptions o;
      o.theta = 1;
      o.gamma0 = gamma0;
      o.linear_solver = solver;
      NitscheSolution s;
      ASSERT_NO_THROW(s = solve_nitsche_contact(b, scene, parabola, o)) << "gamma0 " << gamma0;
      EXPECT_GT(s.lu_fallbacks, 0) << "gamma0 " << gamma0;
      EXPECT_TRUE(s.converged || !s.failure.empty() || s.newton_steps == o.max_newton_steps) << "gamma0 " << gamma0;
      EXPECT_FALSE(std::isnan(s.residual));
    }
}

// The sparse way's Cholesky after a step that was not positive definite: the next positive
// definite step must factorize again, not refactorize a factor the failure left behind.
TEST(NitscheContact, sparse_steps_recover_cholesky_after_an_indefinite_step) {
  const SmallHertz h;
  const ReducedSystem free = eliminate_dirichlet(h.bodies.stiffness(), h.scene.F, h.scene.dirichlet);
  ASSERT_GT(free.K.rows(), 0);
  const int d = free.free_dofs[0];
  const std::vector<Eigen::Triplet<double>> none = {{d, d, 0.0}}, indefinite = {{d, d, -1e3}};
  const Eigen::VectorXd r = Eigen::VectorXd::Ones(free.K.rows());
  const auto steps = make_step_solver(NitscheLinearSolver::sparse, free, {d}, true);
  const Eigen::VectorXd first = steps->solve(none, r);
  EXPECT_EQ(steps->lu_fallbacks(), 0);
  steps->solve(indefinite, r);
  EXPECT_EQ(steps->lu_fallbacks(), 1);
  Eigen::VectorXd again;
  ASSERT_NO_THROW(again = steps->solve(none, r));
  EXPECT_EQ(steps->lu_fallbacks(), 1) << "the positive definite step went to Cholesky again";
  EXPECT_LT((again - first).lpNorm<Eigen::Infinity>(), 1e-12 * first.lpNorm<Eigen::Infinity>());
}
