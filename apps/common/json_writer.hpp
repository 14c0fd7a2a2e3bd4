// A minimal JSON writer for the CLI's --json outputs: numbers with %.17g (DESIGN.md §4; NaN and
// infinities, which JSON cannot hold, become null), escaped strings, nested objects and arrays
// written in order. Header-only so that every command (and the viewer server) can share it.
#pragma once

#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "pgamesh/algebra/pga3.hpp"
#include "pgamesh/core/vec3.hpp"

namespace pgamesh::cli {

class JsonWriter {
 public:
  // Opens/closes an object or array; `key` is used inside an object, empty inside an array.
  JsonWriter& begin_object(std::string_view key = {}) { return open(key, '{'); }
  JsonWriter& end_object() { return close('}'); }
  JsonWriter& begin_array(std::string_view key = {}) { return open(key, '['); }
  JsonWriter& end_array() { return close(']'); }

  JsonWriter& number(std::string_view key, double v) {
    prefix(key);
    if (!std::isfinite(v)) {
      out_ += "null";
    } else {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.17g", v);
      out_ += buf;
    }
    return *this;
  }
  JsonWriter& number(double v) { return number({}, v); }
  JsonWriter& integer(std::string_view key, unsigned long long v) {
    prefix(key);
    out_ += std::to_string(v);
    return *this;
  }
  JsonWriter& boolean(std::string_view key, bool v) {
    prefix(key);
    out_ += v ? "true" : "false";
    return *this;
  }
  JsonWriter& null(std::string_view key = {}) {
    prefix(key);
    out_ += "null";
    return *this;
  }
  JsonWriter& string(std::string_view key, std::string_view v) {
    prefix(key);
    quote(v);
    return *this;
  }
  JsonWriter& string(std::string_view v) { return string({}, v); }

  // A 3-vector as [x, y, z].
  JsonWriter& vec3(std::string_view key, const Vec3d& v) {
    return begin_array(key).number(v.x).number(v.y).number(v.z).end_array();
  }
  JsonWriter& vec3(const Vec3d& v) { return vec3({}, v); }
  // A 3×3 matrix as an array of its rows.
  JsonWriter& matrix3(std::string_view key, const std::array<std::array<double, 3>, 3>& m) {
    begin_array(key);
    for (const auto& row : m)
      begin_array().number(row[0]).number(row[1]).number(row[2]).end_array();
    return end_array();
  }
  // A PGA3 plane (or a sum of face carriers) as {"e0", "e1", "e2", "e3"}.
  JsonWriter& plane(std::string_view key, const pga3::Plane<double>& p) {
    return begin_object(key)
        .number("e0", p.e0)
        .number("e1", p.e1)
        .number("e2", p.e2)
        .number("e3", p.e3)
        .end_object();
  }
  // An array of strings (warnings, reasons, notes).
  JsonWriter& strings(std::string_view key, const std::vector<std::string>& list) {
    begin_array(key);
    for (const auto& s : list) string(s);
    return end_array();
  }

  // The document written so far.
  const std::string& str() const { return out_; }

 private:
  JsonWriter& open(std::string_view key, char c) {
    prefix(key);
    out_ += c;
    first_ = true;
    return *this;
  }
  JsonWriter& close(char c) {
    out_ += c;
    first_ = false;
    return *this;
  }
  void prefix(std::string_view key) {
    if (!first_) out_ += ',';
    first_ = false;
    if (!key.empty()) {
      quote(key);
      out_ += ':';
    }
  }
  void quote(std::string_view s) {
    out_ += '"';
    for (const char ch : s) {
      const auto c = static_cast<unsigned char>(ch);
      if (c == '"' || c == '\\') {
        out_ += '\\';
        out_ += ch;
      } else if (c == '\n') {
        out_ += "\\n";
      } else if (c == '\t') {
        out_ += "\\t";
      } else if (c < 0x20) {
        char buf[8];
        std::snprintf(buf, sizeof buf, "\\u%04x", c);
        out_ += buf;
      } else {
        out_ += ch;
      }
    }
    out_ += '"';
  }

  std::string out_;
  bool first_ = true;
};

}  // namespace pgamesh::cli
