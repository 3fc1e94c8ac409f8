// Figures through gnuplot: a program writes <name>.dat (with a '#' header naming columns and
// units) and <name>.gp, then runs gnuplot to make <name>.png (raster, for the notes) and
// <name>.pdf (vector, for slides) in the same folder, so a lecturer can restyle any figure by
// editing its script: "gnuplot <name>.gp" writes both again. Every figure of the course is
// written by write_figure.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "common/fem/mesh.hpp"

namespace mortar {

struct Series {
  std::string title;
  std::vector<double> x, y;      // a NaN in x breaks the line (used to draw mesh edges)
  std::string style = "linespoints";  // gnuplot "with": lines, points, linespoints, steps
  std::string extra;             // more gnuplot style, e.g. "dt 2 lw 2" or "lc rgb '#888888'"
  bool right_axis = false;       // drawn against the right-hand axis (Figure::y2label)
};

// A dashed line C h^slope through the finest (smallest x) point of series `anchor`, shifted
// down by `offset` so it does not hide the data; or, with `at_coarsest`, through its coarsest
// (largest x) point: a bound drawn there cannot sit above the finer measurements by construction.
// When the anchor series has no point with x > 0 and y > 0 (an error of exactly 0 on a log axis),
// the figure is drawn without that line and a warning names it: a picture never stops a run.
struct ReferenceSlope {
  double slope = 1;
  int anchor = 0;
  double offset = 0.5;
  std::string label;  // default "slope p"
  std::string style;  // gnuplot line style; default reference_slope_style(its place in the list)
  bool at_coarsest = false;
};

// The k-th reference slope's line: its own colour and dash pattern, unlike every other
// reference line and every data series of the course (black, brown, olive, pink with long
// dashes, dash-dot, dots, dash-dot-dot), so two of them can be told apart in greyscale print.
std::string reference_slope_style(std::size_t k);

// The k-th data series' colour: ten dark colours before they repeat (gnuplot's own eight
// repeat sooner, and its fifth, a pale yellow, hides a thin curve on white).
std::string series_colour(std::size_t k);

struct Figure {
  std::string title, xlabel, ylabel;
  bool log_x = false, log_y = false;
  bool equal_axes = false;  // same scale on both axes (meshes)
  std::string key = "top left";
  int width = 900, height = 650;
  std::vector<Series> series;
  std::vector<ReferenceSlope> slopes;
  std::string y2label;                // non-empty: a right-hand axis for the right_axis series
  std::vector<std::string> settings;  // more gnuplot commands before "plot", e.g. "set yrange [0:*]"
  std::vector<Figure> panels;         // drawn below this one in the same file, each its own height
};

// The lines a title is set in on a figure `width` pixels wide: one line when it fits, else
// broken between words (after a colon or a comma past a third of the line where there is one), so
// that no title runs off the picture. A line's width is estimated at 8.5 pixels a character in
// DejaVu Sans 12 (measured: 813 pixels for 102 characters), sub- and superscript marks
// (_ ^ { }) not counted, with 60 pixels kept free for the margins.
std::vector<std::string> title_lines(const std::string& title, int width);

// Writes name.dat and name.gp into folder and, when run_gnuplot, runs gnuplot to make
// name.png (width x height pixels) and name.pdf (the same figure as vector graphics, width/144
// x height/144 inches: the same proportions, fonts and lines as the PNG); throws
// std::runtime_error if gnuplot fails.
void write_figure(const std::string& folder, const std::string& name, const Figure& figure,
                  bool run_gnuplot);

// Error against wall time for a program and for the physical limit of the same levels (the
// floor every chapter compares itself with).
struct TimedErrors {
  std::vector<double> error, time_s, limit_s;
  std::string program_label, limit_label;
};
Figure error_against_time(const std::string& title, const std::string& time_label,
                          const std::string& error_label, const TimedErrors& data);

// Raises the top of a log y axis to `decades` powers of ten above the decade of the highest
// point, so that a key at the top sits over empty space instead of beside the plot.
void room_above_data(Figure& fig, int decades);

// The edges of a mesh as one Series (each triangle's outline; shared edges drawn twice). A P2
// mesh's edges are drawn as the parabolas through their midpoint nodes, so a deformed P2
// element is drawn with the curved edges it has.
Series mesh_edges(const Mesh& mesh, const std::string& title, const std::string& extra = "");

}  // namespace mortar
