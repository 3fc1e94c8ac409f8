#include "common/study/json_writer.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace mortar {

namespace {
std::string quoted(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

std::string number(double v) {
  if (!std::isfinite(v)) return "null";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}
}  // namespace

JsonObject& JsonObject::put(const std::string& key, Value v) {
  for (auto& e : entries_)
    if (e.first == key) {
      e.second = std::move(v);
      return *this;
    }
  entries_.emplace_back(key, std::move(v));
  return *this;
}

JsonObject& JsonObject::merge(const JsonObject& other) {
  for (const auto& [key, value] : other.entries_) put(key, value);
  return *this;
}

JsonObject& JsonObject::set(const std::string& key, double value) { return put(key, value); }
JsonObject& JsonObject::set(const std::string& key, const std::string& value) { return put(key, value); }
JsonObject& JsonObject::set(const std::string& key, bool value) { return put(key, value); }
JsonObject& JsonObject::set(const std::string& key, const JsonObject& value) {
  return put(key, std::make_shared<JsonObject>(value));
}
JsonObject& JsonObject::set(const std::string& key, const std::vector<double>& values) { return put(key, values); }
JsonObject& JsonObject::set(const std::string& key, const std::vector<int>& values) {
  return put(key, std::vector<double>(values.begin(), values.end()));
}

std::string JsonObject::dump(int indent) const {
  const std::string pad(indent + 2, ' ');
  std::ostringstream s;
  s << "{";
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    s << (i ? ",\n" : "\n") << pad << quoted(entries_[i].first) << ": ";
    const Value& v = entries_[i].second;
    if (auto d = std::get_if<double>(&v)) s << number(*d);
    else if (auto t = std::get_if<std::string>(&v)) s << quoted(*t);
    else if (auto b = std::get_if<bool>(&v)) s << (*b ? "true" : "false");
    else if (auto list = std::get_if<std::vector<double>>(&v)) {
      s << "[";
      for (std::size_t k = 0; k < list->size(); ++k) s << (k ? ", " : "") << number((*list)[k]);
      s << "]";
    } else s << std::get<std::shared_ptr<JsonObject>>(v)->dump(indent + 2);
  }
  s << (entries_.empty() ? "}" : "\n" + std::string(indent, ' ') + "}");
  return s.str();
}

}  // namespace mortar
