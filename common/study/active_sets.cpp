#include "common/study/active_sets.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "common/study/plot.hpp"

namespace mortar {

void print_active_sets(const ActiveSetHistory& h) {
  std::printf("active set of %s, step by step:\n", h.label.c_str());
  const std::vector<int> none;
  for (std::size_t k = 0; k < h.steps.size(); ++k) {
    const std::vector<int>& now = h.steps[k];
    const std::vector<int>& before = k > 0 ? h.steps[k - 1] : none;
    std::vector<int> entered, left;
    std::set_difference(now.begin(), now.end(), before.begin(), before.end(), std::back_inserter(entered));
    std::set_difference(before.begin(), before.end(), now.begin(), now.end(), std::back_inserter(left));
    std::printf("  step %2zu: |A| = %4zu, %3zu entered, %3zu left", k + 1, now.size(), entered.size(), left.size());
    if (!now.empty()) std::printf(", nodes from x = %.5g to %.5g", h.x[now.front()], h.x[now.back()]);
    std::printf("\n");
  }
}

void write_active_sets(const std::string& folder, const std::string& title,
                       const std::vector<ActiveSetHistory>& methods, bool run_gnuplot) {
  std::ofstream csv(folder + "/active_sets.csv");
  if (!csv) throw std::runtime_error("cannot write " + folder + "/active_sets.csv");
  csv << "method,step,x,active\n";
  Figure f;
  f.title = title;
  f.xlabel = "x along Γ_c [m]";
  f.ylabel = "Newton step";
  f.key = "below";
  f.height = 520;
  std::size_t steps = 0;
  const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c"};
  for (std::size_t k = 0; k < methods.size(); ++k) {
    const ActiveSetHistory& h = methods[k];
    steps = std::max(steps, h.steps.size());
    // the methods side by side on each step's line, a little above and below it
    const double shift = methods.size() > 1 ? 0.3 * (static_cast<double>(k) / (methods.size() - 1) - 0.5) : 0;
    Series s{h.label + ": active nodes", {}, {}, "points",
             std::string("pt 7 ps 0.5 lc rgb '") + colours[k % 3] + "'"};
    for (std::size_t step = 0; step < h.steps.size(); ++step) {
      std::vector<bool> active(h.x.size(), false);
      for (int i : h.steps[step]) active[i] = true;
      for (std::size_t i = 0; i < h.x.size(); ++i) {
        csv << '"' << h.label << "\"," << step + 1 << ',' << h.x[i] << ',' << (active[i] ? 1 : 0) << '\n';
        if (!active[i]) continue;
        s.x.push_back(h.x[i]);
        s.y.push_back(static_cast<double>(step + 1) + shift);
      }
    }
    f.series.push_back(s);
  }
  // step 1 at the top, the converged set at the bottom, one line per step
  f.settings = {"set yrange [" + std::to_string(steps + 0.7) + ":0.3]", "set ytics 1", "set grid ytics"};
  write_figure(folder, "active_sets", f, run_gnuplot);
}

}  // namespace mortar
