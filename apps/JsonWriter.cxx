#include "JsonWriter.h"

#include <cmath>
#include <cstdio>
#include <sstream>

namespace geolattice {

namespace {
std::string number(double v) {
  if (!std::isfinite(v)) {
    return "null";  // JSON has no NaN/Inf
  }
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}
}  // namespace

std::string jsonQuote(const std::string& text) {
  std::string out = "\"";
  for (unsigned char c : text) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\r':
        out += "\\r";
        break;
      default:
        if (c < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += static_cast<char>(c);
        }
    }
  }
  return out + "\"";
}

JsonObject::Value& JsonObject::slot(const std::string& key) {
  for (auto& e : entries_) {
    if (e.first == key) {
      return e.second;
    }
  }
  entries_.emplace_back(key, Value{});
  return entries_.back().second;
}

JsonObject& JsonObject::set(const std::string& key, double value) {
  slot(key) = Value{number(value), nullptr};
  return *this;
}
JsonObject& JsonObject::set(const std::string& key, long long value) {
  slot(key) = Value{std::to_string(value), nullptr};
  return *this;
}
JsonObject& JsonObject::set(const std::string& key, bool value) {
  slot(key) = Value{value ? "true" : "false", nullptr};
  return *this;
}
JsonObject& JsonObject::set(const std::string& key, const std::string& value) {
  slot(key) = Value{jsonQuote(value), nullptr};
  return *this;
}
JsonObject& JsonObject::set(const std::string& key, const std::vector<double>& values) {
  std::string text = "[";
  for (size_t i = 0; i < values.size(); ++i) {
    text += (i ? ", " : "") + number(values[i]);
  }
  slot(key) = Value{text + "]", nullptr};
  return *this;
}
JsonObject& JsonObject::set(const std::string& key, const std::vector<std::string>& values) {
  std::string text = "[";
  for (size_t i = 0; i < values.size(); ++i) {
    text += (i ? ", " : "") + jsonQuote(values[i]);
  }
  slot(key) = Value{text + "]", nullptr};
  return *this;
}
JsonObject& JsonObject::object(const std::string& key) {
  Value& v = slot(key);
  if (!v.object) {
    v = Value{"", std::make_unique<JsonObject>()};
  }
  return *v.object;
}

void JsonObject::write(std::ostream& os, int indent) const {
  const std::string pad(static_cast<size_t>(indent + 2), ' ');
  os << "{";
  for (size_t i = 0; i < entries_.size(); ++i) {
    os << (i ? ",\n" : "\n") << pad << jsonQuote(entries_[i].first) << ": ";
    if (entries_[i].second.object) {
      entries_[i].second.object->write(os, indent + 2);
    } else {
      os << entries_[i].second.literal;
    }
  }
  os << (entries_.empty() ? "" : "\n") << std::string(static_cast<size_t>(indent), ' ') << "}";
}

}  // namespace geolattice
