// A minimal JSON object writer for summary.json: ordered keys, numbers, strings, booleans
// lists of numbers and nested objects. Non-finite numbers are written as null (JSON has no NaN).
#pragma once

#include <memory>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace mortar {

class JsonObject {
 public:
  JsonObject& set(const std::string& key, double value);
  JsonObject& set(const std::string& key, int value) { return set(key, static_cast<double>(value)); }
  JsonObject& set(const std::string& key, const std::string& value);
  JsonObject& set(const std::string& key, const char* value) { return set(key, std::string(value)); }
  JsonObject& set(const std::string& key, bool value);
  JsonObject& set(const std::string& key, const JsonObject& value);
  // A list of numbers, written on one line: [1, 2, 3]
  JsonObject& set(const std::string& key, const std::vector<double>& values);
  JsonObject& set(const std::string& key, const std::vector<int>& values);

  // Every key of other, in its order (replacing keys this object already has).
  JsonObject& merge(const JsonObject& other);

  std::string dump(int indent = 0) const;
  bool empty() const { return entries_.empty(); }

 private:
  using Value = std::variant<double, std::string, bool, std::shared_ptr<JsonObject>, std::vector<double>>;
  std::vector<std::pair<std::string, Value>> entries_;
  JsonObject& put(const std::string& key, Value v);
};

}  // namespace mortar
