// A minimal JSON writer for the CLI's --json outputs: numbers with %.17g (DESIGN.md §4; NaN and
// infinities, which JSON cannot hold, become null), escaped strings, nested objects and arrays
// written in order. Header-only so that every command (and the viewer server) can share it.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>

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
