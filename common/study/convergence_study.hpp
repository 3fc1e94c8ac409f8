// A convergence study: one row per refinement level, printed as it finishes, then
// convergence.csv and summary.json exactly as README.md's "Output contract" fixes them.
//
// Rates are least-squares slopes of log(err) against log(h) over the three finest levels
// (GSL's gsl_fit_linear), so a rate of 2 means the error falls by 4 when h halves.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "common/study/json_writer.hpp"
#include "common/study/options.hpp"

namespace mortar {

using Row = std::vector<std::pair<std::string, double>>;  // ordered (column, value)

class ConvergenceTable {
 public:
  // Appends a level; the first row fixes the columns, later rows must repeat them in order.
  // Prints the row on one line to stdout so a long study shows its progress.
  void add(const Row& row);

  const std::vector<std::string>& columns() const { return columns_; }
  std::vector<double> column(const std::string& name) const;
  const std::vector<std::vector<double>>& rows() const { return rows_; }
  std::size_t size() const { return rows_.size(); }

  // Slope of log(err_*) vs log(h) over the last `levels` rows, for every err_ column.
  std::map<std::string, double> rates(int levels = 3) const;

  // blank_undefined: a NaN (an undefined rate) is written as an empty field; otherwise every
  // value must be a number, and a NaN is written as such for the contract check to catch.
  void write_csv(const std::string& path, bool blank_undefined = false) const;

  // Local rates: for each level k >= 1 and every err_ column, the slope between levels k - 1
  // and k, log(e_k / e_{k-1}) / log(h_k / h_{k-1}). They show whether a rate has settled,
  // which a fit over three levels hides. Written as local_rates.csv (columns h, then the err_
  // columns; a rate between errors that are 0 is undefined and left blank), and printed as a
  // table.
  ConvergenceTable local_rates() const;
  void print_local_rates() const;

 private:
  std::vector<std::string> columns_;
  std::vector<std::vector<double>> rows_;
};

// Least-squares slope of log(y) against log(x); NaN when fewer than two positive points.
double log_log_slope(const std::vector<double>& x, const std::vector<double>& y);

// summary.json: {"program", "options", "rates", "results"}.
void write_summary(const std::string& path, const OptionParser& options,
                   const std::map<std::string, double>& rates, const JsonObject& results);

// The "options" object of summary.json: numbers as numbers, everything else as strings.
JsonObject options_json(const OptionParser& options);

}  // namespace mortar
