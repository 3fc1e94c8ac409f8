#include "options.hpp"

#include "common/study/bilateral_study.hpp"

#include <cmath>
#include <cstdio>

namespace chapter10 {

using mortar::Range;

namespace {
void add_scene_options(mortar::OptionParser& parser, SceneOptions& s) {
  parser.add_choice("scene", s.name, {"hertz-exact", "bilateral", "punch"},
                    "hertz-exact (exact Hertz, zone half-width L sqrt(2)/29), bilateral (chapter 4's manufactured "
                    "solution) or punch (body 1 a block L/4 wide pressed on body 2: singular corners)");
  parser.add_int("n0", s.n0, "body-1 elements along its contact side on the first mesh (punch: 4 unless given)",
                 Range::closed(2, 4096));
  // h-ratio, nonmortar, E1, nu1, E2, nu2, L, H1, H2 and jitter, as in chapters 3-9 (punch: h-ratio 2,
  // E1 = 10, E2 = 1, nu2 = 0.3 unless given; the punch's block is L/4 wide and tall, whatever H1)
  mortar::add_two_body_options(parser, s.bodies);
  parser.add_double("R", s.R, "hertz-exact: radius of the gap (x - L/2)^2 / (2R) [m]", Range::positive());
  parser.add_double("delta", s.delta, "punch: downward displacement of body 1's top [m]", Range::positive());
}

void add_loop_options(mortar::OptionParser& parser, Options& o) {
  LoopOptions& l = o.loop;
  parser.add_double("theta", l.theta, "Doerfler's share: mark the fewest triangles carrying theta of eta^2 "
                    "(1: every triangle; 0: only the largest)", Range::closed(0, 1));
  parser.add_double("target", l.target, "stop once the estimated relative energy error eta / ||u_h|| is below",
                    Range::open(0, 1));
  parser.add_int("max-steps", l.max_steps, "adaptive steps at most", Range::closed(1, 200));
  parser.add_double("max-dofs", l.max_dofs, "stop before a step (or uniform level) with more unknowns",
                    Range::closed(100, 1e9));
  parser.add_double("uniform-target", o.uniform_target,
                    "uniform refinement runs until this relative energy error (punch: estimated)", Range::open(0, 1));
  parser.add_flag("no-uniform", o.no_uniform, "skip the uniform refinement beside the adaptive loop");
  parser.add_choice("start", o.start, {"nested", "cold"},
                    "each solve's first active set: from the previous step's solution, or none");
  parser.add_choice("refine", o.refine, {"both", "body1", "body2"}, "which bodies the loop may refine");
}
}  // namespace

void parse_options(mortar::OptionParser& parser, Options& o, int argc, char** argv) {
  add_scene_options(parser, o.scene);
  add_loop_options(parser, o);
  parser.add_string("out", o.out, "output folder");
  parser.add_flag("no-plot", o.no_plot, "write data and scripts but do not run gnuplot");
  parser.add_flag("quick", o.quick, "small sizes for tests (target and uniform target 0.1, at most 50000 unknowns unless --max-dofs; not with --target)");
  parser.parse(argc, argv);
  SceneOptions& s = o.scene;
  if (s.name == "punch") {
    if (!parser.given("n0")) s.n0 = 4;
    mortar::TwoBodyOptions& b = s.bodies;
    if (!parser.given("h-ratio")) b.h_ratio = 2;
    // a punch ten times stiffer than its base: the pressure at its corners like r^-0.44
    if (!parser.given("E1")) b.E1 = 10;
    if (!parser.given("E2")) b.E2 = 1;
    if (!parser.given("nu2")) b.nu2 = 0.3;
    // jitter moves the nodes of body 2's contact side, where body 1's corners must find theirs
    if (b.jitter > 0) parser.fail("jitter", "the punch's body 2 needs nodes under body 1's corners: no jitter");
  }
  if (o.quick) {
    if (parser.given("target")) parser.fail("target", "--quick sets the target (0.1); give one or the other");
    o.loop.target = 0.1;
    if (!parser.given("max-dofs")) o.loop.max_dofs = 5e4;
    if (!parser.given("uniform-target")) o.uniform_target = 0.1;
  }
  if (s.name == "punch" && o.loop.max_steps < 6)
    parser.fail("max-steps", "the punch needs at least 6 adaptive steps: 3 for its table and 3 more past --target, "
                             "from which its reference strain energy is extrapolated");
  mortar::check_stiffness_ratio(parser, s.bodies);
  // the softer body carries the multipliers (chapter 5's evidence: a stiff non-mortar side
  // makes the pressure oscillate from node to node)
  o.loop.nonmortar = parser.given("nonmortar") ? s.bodies.nonmortar - 1 : (s.bodies.E1 > s.bodies.E2 ? 1 : 0);
  if (!parser.given("nonmortar") && o.loop.nonmortar == 1)
    std::printf("note: body 1 is %.3g times stiffer than body 2: body 2, the softer, is the non-mortar side "
                "(--nonmortar 1 to force body 1)\n", s.bodies.E1 / s.bodies.E2);
  o.loop.nested = o.start == "nested";
  o.loop.refine_body = {o.refine != "body2", o.refine != "body1"};
  if (s.name != "hertz-exact" && parser.given("R")) parser.fail("R", "only the hertz-exact scene has a gap radius");
  if (s.name != "punch" && parser.given("delta")) parser.fail("delta", "only the punch is driven by --delta");
  mortar::prepare_output_folder(parser, o.out);
}

}  // namespace chapter10
