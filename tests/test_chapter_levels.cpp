// Chapters 3 and 4 take the steps of one bilateral solve one by one in their level.cpp; the
// library's solve_bilateral takes them through make_interface and build_constraints. Both
// must give the same u_h, lambda_h, pressure and jump, on matching and nonmatching meshes,
// with either body as the non-mortar side.
#include <gtest/gtest.h>

#include "03_pointwise_matching/level.hpp"
#include "04_integral_matching/level.hpp"
#include "common/contact/contact_scenes.hpp"

using namespace mortar;

namespace {
void expect_same(const BilateralSolution& steps, const BilateralSolution& library, const char* what) {
  ASSERT_EQ(steps.u.size(), library.u.size()) << what;
  ASSERT_EQ(steps.lambda.size(), library.lambda.size()) << what;
  EXPECT_LE((steps.u - library.u).norm(), 1e-12 * library.u.norm()) << what;
  EXPECT_LE((steps.lambda - library.lambda).norm(), 1e-12 * library.lambda.norm()) << what;
  EXPECT_EQ(steps.constraints.matching, library.constraints.matching) << what;
  EXPECT_EQ(steps.pressure.x, library.pressure.x) << what;
  EXPECT_EQ(steps.jump.x, library.jump.x) << what;
  for (std::size_t k = 0; k < steps.pressure.value.size(); ++k)
    EXPECT_NEAR(steps.pressure.value[k], library.pressure.value[k], 1e-10 * library.pressure.value[k]) << what;
}
}  // namespace

TEST(ChapterLevels, the_steps_of_chapters_3_and_4_give_what_solve_bilateral_gives) {
  const ManufacturedContact exact(Material(1, 0.3), Material(3, 0.25), sloped_profile(1), 1);
  for (int n2 : {8, 5}) {  // matching traces, then nonmatching ones
    const TwoBodyGeometry g{1, 0.5, 0.5, 8, 4, n2, 3, 0.2};  // L, H1, H2, n1, m1, n2, m2, jitter
    const TwoBodies bodies = make_two_bodies(g, exact.material(0), exact.material(1));
    const SceneData scene = manufactured_scene(bodies, exact);
    for (int nonmortar : {0, 1}) {
      BilateralOptions o;
      o.nonmortar = nonmortar;
      o.matching = Matching::pointwise;
      expect_same(chapter03::solve_pointwise_matching(bodies, scene, o), solve_bilateral(bodies, scene, o),
                  "pointwise");
      o.matching = Matching::integral;
      expect_same(chapter04::solve_integral_matching(bodies, scene, o), solve_bilateral(bodies, scene, o),
                  "integral");
    }
  }
}
