#include "common/timing/profile.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <stdexcept>

namespace mortar {

namespace {
double now_seconds() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

// Every phase name of the columns, in first-seen order, then "other".
std::vector<std::string> phase_names(const std::vector<ProfileColumn>& columns) {
  std::vector<std::string> names;
  for (const ProfileColumn& c : columns)
    for (const auto& [name, s] : c.phases)
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(name);
  names.push_back("other");
  return names;
}

// A CSV field: quoted when it holds a comma or a quote.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char ch : text) quoted += ch == '"' ? std::string("\"\"") : std::string(1, ch);
  return quoted + "\"";
}

double seconds_of(const ProfileColumn& c, const std::string& name) {
  double inside = 0;
  for (const auto& [phase, s] : c.phases) {
    if (phase == name) return s;
    inside += s;
  }
  return name == "other" ? std::max(0.0, c.total - inside) : 0.0;
}
}  // namespace

Profile& Profile::current() {
  thread_local Profile profile;
  return profile;
}

void Profile::clear() {
  phases_.clear();
  stack_.clear();
}

double Profile::seconds(const std::string& phase) const {
  for (const auto& [name, s] : phases_)
    if (name == phase) return s;
  return 0.0;
}

double Profile::total() const {
  double t = 0;
  for (const auto& p : phases_) t += p.second;
  return t;
}

void Profile::charge(double now) {
  if (!stack_.empty()) phases_[stack_.back()].second += now - last_;
  last_ = now;
}

void Profile::open(const std::string& phase) {
  charge(now_seconds());
  auto it = std::find_if(phases_.begin(), phases_.end(), [&](const auto& p) { return p.first == phase; });
  if (it == phases_.end()) it = phases_.insert(phases_.end(), {phase, 0.0});
  stack_.push_back(static_cast<std::size_t>(it - phases_.begin()));
}

void Profile::close() {
  charge(now_seconds());
  if (!stack_.empty()) stack_.pop_back();
}

std::string format_profile(const std::vector<ProfileColumn>& columns) {
  std::string text;
  char line[160];
  std::snprintf(line, sizeof line, "%-26s", "phase");
  text += line;
  for (const ProfileColumn& c : columns) {
    std::snprintf(line, sizeof line, " %12s", c.title.c_str());
    text += line;
  }
  text += "\n";
  for (const std::string& name : phase_names(columns)) {
    std::snprintf(line, sizeof line, "%-26s", name.c_str());
    text += line;
    for (const ProfileColumn& c : columns) {
      std::snprintf(line, sizeof line, " %12.4f", seconds_of(c, name));
      text += line;
    }
    text += "\n";
  }
  std::snprintf(line, sizeof line, "%-26s", "total");
  text += line;
  for (const ProfileColumn& c : columns) {
    std::snprintf(line, sizeof line, " %12.4f", c.total);
    text += line;
  }
  return text + "\n";
}

void write_profile_csv(const std::string& path, const std::vector<ProfileColumn>& columns) {
  std::ofstream out(path);
  if (!out) throw std::runtime_error("cannot write " + path);
  out << "phase";
  for (const ProfileColumn& c : columns) out << ',' << csv_field(c.title + "_s");
  out << '\n';
  out.precision(10);
  for (const std::string& name : phase_names(columns)) {
    out << csv_field(name);
    for (const ProfileColumn& c : columns) out << ',' << seconds_of(c, name);
    out << '\n';
  }
  out << "total";
  for (const ProfileColumn& c : columns) out << ',' << c.total;
  out << '\n';
}

}  // namespace mortar
