#include "common/study/plot.hpp"

#include <cctype>
#include <string>
#include <utility>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <sys/wait.h>
#include <unistd.h>

namespace mortar {

namespace {
// Greek letters written out in a label (Gamma_c, lambda_h, sigma_N, psi_i, nu1) set as the
// letters themselves: a name counts when no letter touches it, so "alphabet" or "menu" stay. The terminals read UTF-8 and DejaVu Sans has the glyphs.
std::string greek(const std::string& s) {
  static const std::pair<const char*, const char*> letters[] = {
      {"Gamma", "Γ"}, {"Delta", "Δ"}, {"Lambda", "Λ"}, {"Omega", "Ω"}, {"Sigma", "Σ"}, {"Phi", "Φ"},
      {"Psi", "Ψ"},   {"alpha", "α"}, {"beta", "β"},   {"gamma", "γ"}, {"delta", "δ"}, {"epsilon", "ε"},
      {"theta", "θ"}, {"kappa", "κ"}, {"lambda", "λ"}, {"mu", "μ"},    {"nu", "ν"},    {"xi", "ξ"},
      {"rho", "ρ"},   {"sigma", "σ"}, {"tau", "τ"},    {"phi", "φ"},   {"psi", "ψ"},   {"omega", "ω"}};
  const auto letter = [](char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0; };
  std::string out;
  for (std::size_t i = 0; i < s.size();) {
    bool replaced = false;
    if (letter(s[i]) && (i == 0 || !letter(s[i - 1])))
      for (const auto& [name, glyph] : letters) {
        const std::size_t n = std::char_traits<char>::length(name);
        if (s.compare(i, n, name) == 0 && (i + n == s.size() || !letter(s[i + n]))) {
          out += glyph;
          i += n;
          replaced = true;
          break;
        }
      }
    if (!replaced) out += s[i++];
  }
  return out;
}

// A label for a gnuplot string in single quotes, Greek names set as letters.
std::string escape(const std::string& text) {
  std::string out;
  for (char c : greek(text)) {
    if (c == '\'') out += "''";
    else out += c;
  }
  return out;
}

// The characters of a label as drawn: UTF-8 continuation bytes and the marks of gnuplot's
// enhanced text (_ ^ { }) take no room of their own.
std::size_t drawn_length(const std::string& text) {
  std::size_t n = 0;
  for (unsigned char c : text)
    if ((c & 0xC0) != 0x80 && c != '_' && c != '^' && c != '{' && c != '}') ++n;
  return n;
}

// A title for gnuplot's "set title": its lines in single quotes joined by "\n".
std::string title_expression(const std::string& title, int width) {
  std::string out;
  for (const std::string& line : title_lines(title, width))
    out += (out.empty() ? "'" : ".\"\\n\".'") + escape(line) + "'";
  return out.empty() ? "''" : out;
}

// The figure and its panels, in drawing order (top to bottom).
void collect_panels(const Figure& fig, std::vector<const Figure*>& out) {
  out.push_back(&fig);
  for (const Figure& p : fig.panels) collect_panels(p, out);
}

void write_data(const std::string& path, const std::vector<const Figure*>& panels) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot write " + path);
  f.precision(12);
  f << "# one block per series (gnuplot 'index')\n";
  std::size_t index = 0;
  for (std::size_t p = 0; p < panels.size(); ++p) {
    const Figure& fig = *panels[p];
    f << "# " << (panels.size() > 1 ? "panel " + std::to_string(p + 1) + ": " : "") << fig.title
      << "\n# columns: " << fig.xlabel << ", "
      << (fig.y2label.empty() ? fig.ylabel : fig.ylabel + " (right axis: " + fig.y2label + ")") << "\n";
    for (const Series& ser : fig.series) {
      f << "# series " << index++ << ": " << ser.title << "\n";
      for (std::size_t i = 0; i < ser.x.size() && i < ser.y.size(); ++i) {
        if (std::isnan(ser.x[i])) f << "\n";
        else f << ser.x[i] << " " << ser.y[i] << "\n";
      }
      f << "\n\n";
    }
  }
}

// Runs "gnuplot script" inside folder (the script names its files relative to it), without a
// shell, so no folder name needs quoting.
bool run_in_folder(const std::string& folder, const std::string& script) {
  const pid_t pid = fork();
  if (pid < 0) return false;
  if (pid == 0) {
    if (chdir(folder.c_str()) != 0) _exit(127);
    execlp(MORTAR_GNUPLOT, MORTAR_GNUPLOT, script.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  if (waitpid(pid, &status, 0) != pid) return false;
  return WIFEXITED(status) && WEXITSTATUS(status) == 0;
}

// cairo stamps the PDF with the time it was made, the only byte a rerun would change: a fixed
// date of the same length in its place keeps the file (and its cross-reference offsets) as
// they were, so an unchanged figure stays byte-identical from one run to the next.
void fix_creation_date(const std::filesystem::path& pdf) {
  std::string bytes;
  {
    std::ifstream in(pdf, std::ios::binary);
    if (!in) return;
    std::ostringstream s;
    s << in.rdbuf();
    bytes = s.str();
  }
  const std::string key = "/CreationDate (";
  const std::size_t at = bytes.find(key);
  if (at == std::string::npos) return;
  const std::size_t begin = at + key.size(), end = bytes.find(')', begin);
  const std::string fixed = "D:19700101000000Z";
  if (end == std::string::npos || end - begin != fixed.size()) return;
  bytes.replace(begin, fixed.size(), fixed);
  std::ofstream(pdf, std::ios::binary | std::ios::trunc) << bytes;
}

// C with C x0^p = (1 - offset) y(x0) at the anchor series' smallest x (or largest: at_coarsest);
// empty when the series has no point with x > 0 and y > 0 (a measured error of exactly 0, say):
// such a line has nothing to pass through, and the figure is drawn without it
std::string slope_function(const Figure& fig, const ReferenceSlope& r, std::size_t k) {
  if (r.anchor < 0 || r.anchor >= static_cast<int>(fig.series.size()))
    throw std::invalid_argument("reference slope anchored to a missing series");
  const auto& s = fig.series[r.anchor];
  double x0 = std::numeric_limits<double>::infinity(), y0 = 0;
  for (std::size_t i = 0; i < s.x.size(); ++i)
    if (s.x[i] > 0 && s.y[i] > 0 && (!std::isfinite(x0) || (r.at_coarsest ? s.x[i] > x0 : s.x[i] < x0))) {
      x0 = s.x[i];
      y0 = s.y[i];
    }
  if (!std::isfinite(x0)) return "";
  std::ostringstream f;
  f.precision(12);
  f << "ref" << k << "(x) = " << (1 - r.offset) * y0 / std::pow(x0, r.slope) << " * x**("
    << r.slope << ")\n";
  return f.str();
}

// The reference slopes of a figure that can be drawn; a warning on stderr names each one left out.
std::vector<std::pair<ReferenceSlope, std::string>> drawable_slopes(const Figure& fig, const std::string& name,
                                                                    std::size_t& next) {
  std::vector<std::pair<ReferenceSlope, std::string>> out;
  for (const ReferenceSlope& r : fig.slopes) {
    const std::string f = slope_function(fig, r, next);
    if (f.empty()) {
      std::fprintf(stderr, "warning: figure %s: reference slope %g left out (series '%s' has no positive point)\n",
                   name.c_str(), r.slope, fig.series[r.anchor].title.c_str());
      continue;
    }
    out.emplace_back(r, f);
    ++next;
  }
  return out;
}
}  // namespace

std::string series_colour(std::size_t k) {
  static const char* colours[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                                  "#8c564b", "#e377c2", "#17becf", "#7f7f7f", "#bcbd22"};
  return colours[k % 10];
}

std::string reference_slope_style(std::size_t k) {
  static const char* styles[] = {
      "dt (16,6) lw 2.5 lc rgb '#000000'",            // black, long dashes
      "dt (12,5,3,5) lw 2.5 lc rgb '#8c564b'",        // brown, dash-dot
      "dt (3,4) lw 3 lc rgb '#bcbd22'",               // olive, dots
      "dt (12,4,3,4,3,4) lw 2.5 lc rgb '#e377c2'",    // pink, dash-dot-dot
  };
  return styles[k % 4];
}

std::vector<std::string> title_lines(const std::string& title, int width) {
  const std::size_t room = static_cast<std::size_t>(std::max(20.0, (width - 60) / 8.5));
  const std::string text = greek(title);
  std::vector<std::string> lines;
  std::string line;
  std::istringstream words(text);
  std::string word;
  while (words >> word) {
    const std::string longer = line.empty() ? word : line + " " + word;
    if (line.empty() || drawn_length(longer) <= room) {
      line = longer;
      continue;
    }
    // break after the last colon or comma of the line when it is past a third of the room, so that
    // the title splits where its parts meet rather than mid-phrase
    const std::size_t colon = line.rfind(": "), comma = line.rfind(", ");
    std::size_t mark = colon == std::string::npos ? comma : comma == std::string::npos ? colon : std::max(colon, comma);
    if (mark != std::string::npos && drawn_length(line.substr(0, mark + 1)) > room / 3) {
      lines.push_back(line.substr(0, mark + 1));
      line = line.substr(mark + 2) + " " + word;
    } else {
      lines.push_back(line);
      line = word;
    }
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

void write_figure(const std::string& folder, const std::string& name, const Figure& figure,
                  bool run_gnuplot) {
  namespace fs = std::filesystem;
  std::vector<const Figure*> panels;
  collect_panels(figure, panels);
  write_data((fs::path(folder) / (name + ".dat")).string(), panels);

  int width = 0, height = 0;
  for (const Figure* p : panels) {
    width = std::max(width, p->width);
    height += p->height;
  }
  const bool multiplot = panels.size() > 1;
  std::ostringstream gp;
  gp.precision(6);
  gp << "# " << name << ".png (" << width << " x " << height << " pixels) and " << name
     << ".pdf (vector, the same proportions) from the same commands\n"
     << "do for [format in 'png pdf'] {\n"
     << "reset\n"
     << "set encoding utf8\n"
     << "if (format eq 'png') {\n"
     << "  set terminal pngcairo size " << width << "," << height << " enhanced font 'DejaVu Sans,12'\n"
     << "  set output '" << name << ".png'\n"
     << "} else {\n"
     << "  set terminal pdfcairo size " << width / 144.0 << "in," << height / 144.0
     << "in enhanced font 'DejaVu Sans,12'\n"
     << "  set output '" << name << ".pdf'\n"
     << "}\n";
  if (multiplot) gp << "set multiplot\n";
  std::size_t index = 0, slope = 0;
  double top = 1.0;
  for (const Figure* p : panels) {
    const Figure& fig = *p;
    if (multiplot) {
      const double h = static_cast<double>(fig.height) / height;
      top -= h;
      gp << (p == panels.front() ? "" : "reset\n") << "set origin 0," << std::max(0.0, top) << "\n"
         << "set size " << static_cast<double>(fig.width) / width << "," << h << "\n";
    }
    gp << "set title " << title_expression(fig.title, fig.width) << "\n"
       << "set xlabel '" << escape(fig.xlabel) << "'\n"
       << "set ylabel '" << escape(fig.ylabel) << "'\n"
       << "set key " << fig.key << " box opaque spacing 1.15\n"
       << "set grid\n";
    if (fig.log_x) gp << "set logscale x\nset format x '10^{%L}'\n";
    if (fig.log_y) gp << "set logscale y\nset format y '10^{%L}'\n";
    if (fig.equal_axes) gp << "set size ratio -1\n";
    if (!fig.y2label.empty())
      gp << "set y2label '" << escape(fig.y2label) << "'\nset ytics nomirror\nset y2tics\n";
    for (const std::string& c : fig.settings) gp << c << "\n";
    const std::size_t first_slope = slope;
    const auto slopes = drawable_slopes(fig, name, slope);
    for (const auto& r : slopes) gp << r.second;
    gp << "plot ";
    for (std::size_t s = 0; s < fig.series.size(); ++s) {
      const Series& ser = fig.series[s];
      gp << (s ? ", \\\n     " : "") << "'" << name << ".dat' index " << index++ << " using 1:2"
         << (ser.right_axis ? " axes x1y2" : "") << " with " << ser.style << " " << ser.extra << " title '"
         << escape(ser.title) << "'";
    }
    for (std::size_t k = 0; k < slopes.size(); ++k) {
      const ReferenceSlope& r = slopes[k].first;
      std::ostringstream label;
      label << (r.label.empty() ? "slope " : r.label);
      if (r.label.empty()) label << r.slope;
      gp << ", \\\n     ref" << first_slope + k << "(x) with lines "
         << (r.style.empty() ? reference_slope_style(k) : r.style) << " title '" << escape(label.str()) << "'";
    }
    gp << "\n";
  }
  if (multiplot) gp << "unset multiplot\n";
  gp << "set output\n}\n";
  const fs::path script = fs::path(folder) / (name + ".gp");
  {
    std::ofstream f(script);
    if (!f) throw std::runtime_error("cannot write " + script.string());
    f << gp.str();
  }
  std::error_code ignored;
  for (const char* ext : {".png", ".pdf"})  // never leave a figure from an earlier run beside new data
    fs::remove(fs::path(folder) / (name + ext), ignored);
  if (!run_gnuplot) return;
  if (!run_in_folder(folder, name + ".gp"))
    throw std::runtime_error("gnuplot (" MORTAR_GNUPLOT ") failed on " + script.string());
  fix_creation_date(fs::path(folder) / (name + ".pdf"));
}

Figure error_against_time(const std::string& title, const std::string& time_label,
                          const std::string& error_label, const TimedErrors& d) {
  Figure fig;
  fig.title = title;
  fig.xlabel = time_label;
  fig.ylabel = error_label;
  fig.log_x = fig.log_y = true;
  fig.key = "top right";
  fig.series.push_back({d.program_label, d.time_s, d.error, "linespoints", "pt 7 lw 2"});
  fig.series.push_back({d.limit_label, d.limit_s, d.error, "linespoints", "pt 4 lw 1 dt 3"});
  return fig;
}

void room_above_data(Figure& fig, int decades) {
  double top = 0;
  for (const Series& s : fig.series)
    for (double y : s.y)
      if (std::isfinite(y)) top = std::max(top, y);
  if (!(top > 0)) return;  // nothing drawn: gnuplot's own range
  char range[64];
  std::snprintf(range, sizeof range, "set yrange [:%.0e]", std::pow(10.0, std::ceil(std::log10(top)) + decades));
  fig.settings.push_back(range);
}

Series mesh_edges(const Mesh& mesh, const std::string& title, const std::string& extra) {
  Series s;
  s.title = title;
  s.style = "lines";
  s.extra = extra;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  // A P2 edge is the parabola through its two ends and its midpoint node: once the nodes are
  // moved by u_h it bends, and a straight line between the ends would not be the element.
  // Drawn as 8 chords, Lagrange's quadratic interpolation at s = 0, 1/8, ..., 1.
  const int chords = mesh.degree() == 2 ? 8 : 1;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& v = mesh.triangles[t];
    for (int k = 0; k < 3; ++k) {
      const Eigen::Vector2d& a = mesh.nodes[v[k]];
      const Eigen::Vector2d& b = mesh.nodes[v[(k + 1) % 3]];
      // edge k of a P2 triangle runs from vertex k to vertex k + 1, midpoint edge_nodes[t][k]
      const Eigen::Vector2d m = chords > 1 ? mesh.nodes[mesh.edge_nodes[t][k]] : Eigen::Vector2d(0.5 * (a + b));
      for (int j = k == 0 ? 0 : 1; j <= chords; ++j) {
        const double r = static_cast<double>(j) / chords;
        const Eigen::Vector2d p = (1 - r) * (1 - 2 * r) * a + 4 * r * (1 - r) * m + r * (2 * r - 1) * b;
        s.x.push_back(p.x());
        s.y.push_back(p.y());
      }
    }
    s.x.push_back(nan);
    s.y.push_back(nan);
  }
  return s;
}

}  // namespace mortar
