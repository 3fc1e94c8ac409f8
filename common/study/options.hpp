// Command-line options: one parser for every chapter program.
//
// A program declares each option once (name, target variable, help text, allowed range);
// the parser fills the targets, prints `--help` with every default, and turns any unknown
// option or invalid value into a message naming the option and exit status 2.
#pragma once

#include <functional>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace mortar {

// Closed or open bounds for a numeric option; infinite bounds mean "no bound".
struct Range {
  double lo;
  double hi;
  bool lo_open;
  bool hi_open;
  static Range any();
  static Range positive();                       // (0, inf)
  static Range non_negative();                   // [0, inf)
  static Range closed(double lo, double hi);     // [lo, hi]
  static Range open(double lo, double hi);       // (lo, hi)
  static Range half_open(double lo, double hi);  // [lo, hi)
  bool contains(double v) const;
  std::string describe() const;
};

class OptionParser {
 public:
  OptionParser(std::string program, std::string summary);
  OptionParser(const OptionParser&) = delete;  // options hold references to their targets
  OptionParser& operator=(const OptionParser&) = delete;

  void add_int(const std::string& name, int& target, const std::string& help, Range range);
  // Accepts decimals and fractions such as "3/2" (mesh ratios read better that way).
  void add_double(const std::string& name, double& target, const std::string& help, Range range);
  void add_string(const std::string& name, std::string& target, const std::string& help);
  void add_choice(const std::string& name, std::string& target, std::vector<std::string> choices,
                  const std::string& help);
  void add_flag(const std::string& name, bool& target, const std::string& help);

  // Parses argv; on --help prints usage and exits 0, on any error calls fail() (exit 2).
  void parse(int argc, const char* const* argv);

  // Whether the command line set this option (so a program can choose defaults that
  // depend on other options, such as the scene).
  bool given(const std::string& name) const;

  // --quick (small sizes for tests): when quick, sets each listed int option to its small
  // value, and refuses (status 2) any of them given as well, which --quick would override.
  struct QuickSize {
    const char* name;
    int& target;
    int value;
  };
  void apply_quick(bool quick, std::initializer_list<QuickSize> sizes) const;

  // Prints "<program>: --name: message" on stderr and exits with status 2.
  [[noreturn]] void fail(const std::string& name, const std::string& message) const;

  // Every option with the value in use, in declaration order, for summary.json;
  // numeric() tells which of them are numbers.
  std::vector<std::pair<std::string, std::string>> values() const;
  std::vector<bool> numeric() const;
  std::string usage() const;
  const std::string& program() const { return program_; }

 private:
  struct Option {
    std::string name;
    std::string help;
    bool is_flag = false;
    bool is_numeric = false;
    std::function<std::string(const std::string&)> set;  // returns "" or an error message
    std::function<std::string()> show;
  };
  const Option* find(const std::string& name) const;

  std::string program_;
  std::string summary_;
  bool help_ = false;
  std::vector<Option> options_;
  std::vector<std::string> given_;
};

// Parses a finite double, also "p/q"; returns false for anything else (NaN, inf, junk).
bool parse_number(const std::string& text, double& value);

// Creates the output folder of a program; a folder that cannot be created or written is a
// bad --out value (exit 2), reported before any computation starts, and the folders made on
// the way are removed again. The previous run's convergence.csv and summary.json are removed,
// so that a run that fails later does not leave them looking like its own.
void prepare_output_folder(const OptionParser& parser, const std::string& folder);

// The files a run writes into its output folder are listed in FOLDER/.outputs when the program
// ends (the regular files written since the folder was prepared). The next run into the folder
// removes exactly those before it starts, so a part it skips leaves no stale file, and nothing
// the program did not write is touched. prepare_output_folder calls both.
void remove_previous_outputs(const std::string& folder);
void record_outputs_at_exit(const std::string& folder);

}  // namespace mortar
