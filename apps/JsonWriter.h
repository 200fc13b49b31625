#pragma once
/// @file JsonWriter.h
/// @brief A tiny ordered JSON object model for report.json (numbers, strings, booleans,
/// arrays of numbers or strings, nested objects), printed with stable key order.
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace geolattice {

/// @class JsonObject
/// @brief Keys keep their insertion order; set() on an existing key replaces its value.
class JsonObject {
public:
  JsonObject& set(const std::string& key, double value);
  JsonObject& set(const std::string& key, long long value);
  JsonObject& set(const std::string& key, int value) {
    return set(key, static_cast<long long>(value));
  }
  JsonObject& set(const std::string& key, bool value);
  JsonObject& set(const std::string& key, const std::string& value);
  JsonObject& set(const std::string& key, const char* value) {
    return set(key, std::string(value));
  }
  JsonObject& set(const std::string& key, const std::vector<double>& values);
  JsonObject& set(const std::string& key, const std::vector<std::string>& values);
  /// The nested object under key (created if missing).
  JsonObject& object(const std::string& key);

  void write(std::ostream& os, int indent = 0) const;

private:
  struct Value {
    std::string literal;                 // already-encoded JSON text, or empty for an object
    std::unique_ptr<JsonObject> object;  // non-null for a nested object
  };
  Value& slot(const std::string& key);
  std::vector<std::pair<std::string, Value>> entries_;
};

/// JSON string literal with escapes.
std::string jsonQuote(const std::string& text);

}  // namespace geolattice
