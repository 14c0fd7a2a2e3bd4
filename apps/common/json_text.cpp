#include "json_text.hpp"

#include <cmath>

#include "pgamesh/core/number_text.hpp"

namespace pgamesh::cli {

namespace {

// A string as JSON: plain ASCII as it is; anything else through nlohmann's escaping (bytes that are
// not UTF-8 become U+FFFD).
void write_string(std::string& out, const std::string& text) {
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x20 || c >= 0x80 || c == '"' || c == '\\') {
      out += Json(text).dump(-1, ' ', false, Json::error_handler_t::replace);
      return;
    }
  }
  out += '"';
  out += text;
  out += '"';
}

void write(std::string& out, const Json& j) {
  switch (j.type()) {
    case Json::value_t::object: {
      out += '{';
      bool first = true;
      for (auto it = j.begin(); it != j.end(); ++it) {
        if (!first) out += ',';
        first = false;
        write_string(out, it.key());
        out += ':';
        write(out, it.value());
      }
      out += '}';
      return;
    }
    case Json::value_t::array: {
      out += '[';
      bool first = true;
      for (const Json& v : j) {
        if (!first) out += ',';
        first = false;
        write(out, v);
      }
      out += ']';
      return;
    }
    case Json::value_t::number_float: {
      const double v = j.get<double>();
      out += std::isfinite(v) ? format_number(v) : "null";
      return;
    }
    case Json::value_t::string:
      write_string(out, j.get_ref<const std::string&>());
      return;
    default:  // null, booleans, integers
      out += j.dump(-1, ' ', false, Json::error_handler_t::replace);
      return;
  }
}

bool finite(std::initializer_list<double> values) {
  for (double v : values)
    if (!std::isfinite(v)) return false;
  return true;
}

}  // namespace

std::string json_text(const Json& document) {
  std::string out;
  write(out, document);
  return out;
}

Json json_number(double v) {
  return std::isfinite(v) ? Json(v) : Json(nullptr);
}

Json json_range(double low, double high) {
  if (!finite({low, high})) return nullptr;
  return Json::array({low, high});
}

Json json_vec3(const Vec3d& v) {
  if (!finite({v.x, v.y, v.z})) return nullptr;
  return Json::array({v.x, v.y, v.z});
}

Json json_matrix3(const std::array<std::array<double, 3>, 3>& m) {
  Json rows = Json::array();
  for (const auto& row : m) {
    if (!finite({row[0], row[1], row[2]})) return nullptr;
    rows.push_back(Json::array({row[0], row[1], row[2]}));
  }
  return rows;
}

Json json_plane(const pga3::Plane<double>& p) {
  if (!finite({p.e0, p.e1, p.e2, p.e3})) return nullptr;
  return Json{{"e0", p.e0}, {"e1", p.e1}, {"e2", p.e2}, {"e3", p.e3}};
}

Json json_strings(const std::vector<std::string>& list) {
  Json a = Json::array();
  for (const auto& s : list) a.push_back(s);
  return a;
}

}  // namespace pgamesh::cli
