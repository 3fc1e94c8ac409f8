#include "common/study/convergence_study.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_fit.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <stdexcept>

namespace mortar {

void ConvergenceTable::add(const Row& row) {
  if (rows_.empty() && columns_.empty())
    for (const auto& [name, value] : row) columns_.push_back(name);
  if (row.size() != columns_.size())
    throw std::invalid_argument("ConvergenceTable::add: row has " + std::to_string(row.size()) +
                                " columns, table has " + std::to_string(columns_.size()));
  std::vector<double> values;
  for (std::size_t i = 0; i < row.size(); ++i) {
    if (row[i].first != columns_[i])
      throw std::invalid_argument("ConvergenceTable::add: column " + std::to_string(i) + " is '" +
                                  row[i].first + "', expected '" + columns_[i] + "'");
    values.push_back(row[i].second);
  }
  rows_.push_back(values);

  std::printf("level %zu:", rows_.size() - 1);
  for (const auto& [name, value] : row) std::printf("  %s=%.4g", name.c_str(), value);
  std::printf("\n");
  std::fflush(stdout);
}

std::vector<double> ConvergenceTable::column(const std::string& name) const {
  for (std::size_t c = 0; c < columns_.size(); ++c)
    if (columns_[c] == name) {
      std::vector<double> out;
      for (const auto& r : rows_) out.push_back(r[c]);
      return out;
    }
  throw std::invalid_argument("ConvergenceTable: no column '" + name + "'");
}

double log_log_slope(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<double> lx, ly;
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i)
    if (x[i] > 0 && y[i] > 0 && std::isfinite(x[i]) && std::isfinite(y[i])) {
      lx.push_back(std::log(x[i]));
      ly.push_back(std::log(y[i]));
    }
  if (lx.size() < 2) return std::numeric_limits<double>::quiet_NaN();
  gsl_set_error_handler_off();
  double c0, c1, cov00, cov01, cov11, sumsq;
  const int status = gsl_fit_linear(lx.data(), 1, ly.data(), 1, lx.size(), &c0, &c1, &cov00,
                                    &cov01, &cov11, &sumsq);
  if (status != GSL_SUCCESS) return std::numeric_limits<double>::quiet_NaN();
  return c1;
}

std::map<std::string, double> ConvergenceTable::rates(int levels) const {
  std::map<std::string, double> out;
  const std::vector<double> h = column("h");
  const std::size_t first = rows_.size() > static_cast<std::size_t>(levels) ? rows_.size() - levels : 0;
  const std::vector<double> h_tail(h.begin() + first, h.end());
  for (const auto& name : columns_)
    if (name.rfind("err_", 0) == 0) {
      const std::vector<double> e = column(name);
      out[name] = log_log_slope(h_tail, std::vector<double>(e.begin() + first, e.end()));
    }
  return out;
}

void ConvergenceTable::write_csv(const std::string& path, bool blank_undefined) const {
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot write " + path);
  for (std::size_t c = 0; c < columns_.size(); ++c) f << (c ? "," : "") << columns_[c];
  f << "\n";
  char buf[32];
  for (const auto& r : rows_) {
    for (std::size_t c = 0; c < r.size(); ++c) {
      if (blank_undefined && !std::isfinite(r[c])) buf[0] = '\0';
      else std::snprintf(buf, sizeof buf, "%.10g", r[c]);
      f << (c ? "," : "") << buf;
    }
    f << "\n";
  }
}

ConvergenceTable ConvergenceTable::local_rates() const {
  ConvergenceTable out;
  const std::vector<double> h = column("h");
  for (std::size_t k = 1; k < rows_.size(); ++k) {
    std::vector<double> values{h[k]};
    for (std::size_t c = 0; c < columns_.size(); ++c)
      if (columns_[c].rfind("err_", 0) == 0)
        values.push_back(log_log_slope({h[k - 1], h[k]}, {rows_[k - 1][c], rows_[k][c]}));
    out.rows_.push_back(values);
  }
  out.columns_.push_back("h");
  for (const auto& name : columns_)
    if (name.rfind("err_", 0) == 0) out.columns_.push_back(name);
  return out;
}

void ConvergenceTable::print_local_rates() const {
  const ConvergenceTable local = local_rates();
  std::printf("local rates, level k-1 to k:\n  %5s %10s", "k", "h");
  for (std::size_t c = 1; c < local.columns_.size(); ++c) std::printf(" %*s", std::max<int>(8, local.columns_[c].size() - 4), local.columns_[c].substr(4).c_str());
  std::printf("\n");
  bool undefined = false;
  for (std::size_t k = 0; k < local.rows_.size(); ++k) {
    std::printf("  %5zu %10.4g", k + 1, local.rows_[k][0]);
    for (std::size_t c = 1; c < local.columns_.size(); ++c) {
      const int width = std::max<int>(8, local.columns_[c].size() - 4);
      if (std::isnan(local.rows_[k][c])) std::printf(" %*s", width, "-");
      else std::printf(" %*.3f", width, local.rows_[k][c]);
      undefined = undefined || std::isnan(local.rows_[k][c]);
    }
    std::printf("\n");
  }
  if (undefined) std::printf("  (-: undefined, an error of zero on one of the two levels)\n");
  std::fflush(stdout);
}

JsonObject options_json(const OptionParser& options) {
  JsonObject o;
  const auto values = options.values();
  const auto numeric = options.numeric();
  for (std::size_t i = 0; i < values.size(); ++i) {
    const auto& [name, text] = values[i];
    if (numeric[i]) o.set(name, std::stod(text));
    else if (text == "true" || text == "false") o.set(name, text == "true");
    else o.set(name, text);
  }
  return o;
}

void write_summary(const std::string& path, const OptionParser& options,
                   const std::map<std::string, double>& rates, const JsonObject& results) {
  JsonObject rate_object;
  for (const auto& [name, value] : rates) rate_object.set(name, value);
  JsonObject summary;
  summary.set("program", options.program())
      .set("options", options_json(options))
      .set("rates", rate_object)
      .set("results", results);
  std::ofstream f(path);
  if (!f) throw std::runtime_error("cannot write " + path);
  f << summary.dump() << "\n";
}

}  // namespace mortar
