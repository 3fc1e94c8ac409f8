#include "comparisons.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>

#include "common/timing/stopwatch.hpp"

namespace chapter08 {

std::vector<SolverRun> compare_solvers(const Options& o, const std::vector<double>& frictions, int finest_level) {
  std::vector<SolverRun> runs;
  const mortar::Material m1(o.E1, o.nu1), m2(o.E2, o.nu2);
  for (double F : frictions)
    for (int level = 0; level <= finest_level; ++level) {
      // over h at the chosen F, over F at the finest level only
      if (F != o.friction && level != finest_level) continue;
      Options p = o;
      p.friction = F;
      p.law = "coulomb";
      p.solver = "newton";  // the first run is Newton's, whatever --solver says
      const mortar::ManufacturedFriction exact(m1, m2, o.L, F);
      const Scene scene = make_scene(scene_parameters(p), exact);
      SolverRun run;
      run.friction = F;
      run.level = level;
      LevelSetup setup = level_setup(p, level);
      setup.repetitions = {1, 1, 0.0};
      const FrictionalLevel newton = solve_frictional_level(setup, scene, m1, m2);
      setup.fixed_point = true;
      setup.measure_limit = false;
      const FrictionalLevel fixed = solve_frictional_level(setup, scene, m1, m2);
      run.h1 = newton.h1;
      run.dofs = newton.bodies.num_dofs();
      run.newton_steps = newton.newton_steps_total();
      run.newton_lu_steps = newton.lu_steps_total();
      run.fixed_point_outer = fixed.last().outer_iterations;
      run.fixed_point_steps = fixed.newton_steps_total();
      run.newton_s = newton.time_s;
      run.fixed_point_s = fixed.time_s;
      run.limit_s = newton.limit_s;
      run.difference = (newton.last().u - fixed.last().u).norm() / newton.last().u.norm();
      std::printf("solvers: F = %.2f level %d (%d dofs): Newton %d steps (%d with an LU) %.3f s; fixed point %d Tresca "
                  "problems, %d steps, %.3f s; limit %.3f s; answers differ by %.1e\n",
                  F, level, run.dofs, run.newton_steps, run.newton_lu_steps, run.newton_s, run.fixed_point_outer,
                  run.fixed_point_steps, run.fixed_point_s, run.limit_s, run.difference);
      runs.push_back(run);
    }
  return runs;
}

void write_solver_runs(const std::string& path, const std::vector<SolverRun>& runs) {
  std::ofstream out(path);
  out << "friction,level,h1,dofs,newton_steps,newton_lu_steps,newton_s,fixed_point_outer,fixed_point_steps,"
         "fixed_point_s,limit_s,difference\n";
  char line[300];
  for (const SolverRun& r : runs) {
    std::snprintf(line, sizeof line, "%.4g,%d,%.8g,%d,%d,%d,%.6g,%d,%d,%.6g,%.6g,%.3g\n", r.friction, r.level, r.h1,
                  r.dofs, r.newton_steps, r.newton_lu_steps, r.newton_s, r.fixed_point_outer, r.fixed_point_steps,
                  r.fixed_point_s, r.limit_s, r.difference);
    out << line;
  }
  if (!out) throw std::runtime_error("cannot write " + path);
}

std::vector<PathRun> compare_paths(const Options& o, int level) {
  const mortar::Material m1(o.E1, o.nu1), m2(o.E2, o.nu2);
  const mortar::ManufacturedFriction unused(m1, m2, o.L, o.friction);  // the scene reads only its materials
  std::vector<PathRun> runs;
  LevelSetup setup = level_setup(o, level);
  setup.measure_limit = false;
  // 1. The chapter's path: P, then Q in load_steps steps.
  const FrictionalLevel standard = solve_frictional_level(setup, make_scene(scene_parameters(o), unused), m1, m2);
  const double P = standard.steps.front().normal_force;
  const auto record = [&](const std::string& name, const FrictionalLevel& r) {
    PathRun run;
    run.path = name;
    run.steps = static_cast<int>(r.steps.size());
    run.newton_steps = r.newton_steps_total();
    run.q_ratio = r.last().shear_force / (o.friction * r.last().normal_force);
    run.c_h = stick_zone(r.last()).half_width();
    mortar::InterfaceCurve closed = r.last().pressure;  // the nodes not open (round-off leaves tiny lambda_n elsewhere)
    for (std::size_t k = 0; k < closed.value.size(); ++k)
      closed.value[k] = r.last().status[k] != mortar::NodeStatus::open ? 1.0 : 0.0;
    run.contact_half_width = mortar::contact_zone(closed).half_width();
    run.shear_difference = mortar::relative_l2_difference(r.last().shear, standard.last().shear);
    std::printf("path %-34s %2d steps (%3d Newton steps): Q/(F P) = %.4f, stick half-width %.5f m, contact %.5f m, "
                "shear differs from the first path by %.3g\n",
                name.c_str(), run.steps, run.newton_steps, run.q_ratio, run.c_h, run.contact_half_width,
                run.shear_difference);
    runs.push_back(run);
  };
  char name[80];
  std::snprintf(name, sizeof name, "P then Q in %d steps", o.load_steps);
  record(name, standard);
  // 2. The same loads, Q in one step.
  SceneParameters one = scene_parameters(o);
  one.load_steps = 1;
  record("P then Q in 1 step", solve_frictional_level(setup, make_scene(one, unused), m1, m2));
  // 3. P and Q together, in load_steps proportional steps, to the same final Q (Mindlin).
  SceneParameters together = scene_parameters(o);
  together.proportional = true;
  LevelSetup proportional = setup;
  proportional.normal_force = P;
  std::snprintf(name, sizeof name, "P and Q together in %d steps", o.load_steps);
  record(name, solve_frictional_level(proportional, make_scene(together, unused), m1, m2));
  return runs;
}

void write_path_runs(const std::string& path, const std::vector<PathRun>& runs) {
  std::ofstream out(path);
  out << "path,steps,newton_steps,q_ratio,stick_half_width,contact_half_width,shear_difference\n";
  char line[300];
  for (const PathRun& r : runs) {
    std::snprintf(line, sizeof line, "%s,%d,%d,%.6f,%.8g,%.8g,%.4g\n", r.path.c_str(), r.steps, r.newton_steps,
                  r.q_ratio, r.c_h, r.contact_half_width, r.shear_difference);
    out << line;
  }
  if (!out) throw std::runtime_error("cannot write " + path);
}

}  // namespace chapter08
