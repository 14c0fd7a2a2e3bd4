// Point lists, point files and vector printing for the model commands.
#include "models_args.hpp"

#include <cctype>
#include <charconv>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>

#include "commands.hpp"
#include "pgamesh/core/input_error.hpp"
#include "pgamesh/core/number_text.hpp"
#include "pgamesh/io/read_mesh.hpp"

namespace pgamesh::cli {

namespace {

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

// A number, "nan" or "inf" (any case, with a sign): the non-finite ones are the models' to refuse.
std::optional<double> number_or_special(std::string_view t) {
  t = trim(t);
  if (auto v = parse_number(t)) return v;
  std::string lower;
  for (char c : t) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const bool negative = !lower.empty() && lower[0] == '-';
  if (!lower.empty() && (lower[0] == '-' || lower[0] == '+')) lower.erase(0, 1);
  if (lower == "nan") return std::numeric_limits<double>::quiet_NaN();
  if (lower == "inf" || lower == "infinity")
    return negative ? -std::numeric_limits<double>::infinity()
                    : std::numeric_limits<double>::infinity();
  return std::nullopt;
}

std::vector<std::string_view> split(std::string_view s, char sep) {
  std::vector<std::string_view> out;
  for (;;) {
    const std::size_t k = s.find(sep);
    out.push_back(s.substr(0, k));
    if (k == std::string_view::npos) return out;
    s.remove_prefix(k + 1);
  }
}

bool has_suffix(std::string_view path, std::string_view ext) {
  if (path.size() < ext.size()) return false;
  for (std::size_t i = 0; i < ext.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(path[path.size() - ext.size() + i])) != ext[i])
      return false;
  return true;
}

}  // namespace

std::vector<double> parse_number_list(const std::string& option, std::string_view text,
                                      std::size_t count) {
  std::vector<double> out;
  for (std::string_view t : split(text, ',')) {
    const auto v = number_or_special(t);
    if (!v)
      throw UsageError(option + ": '" + std::string(trim(t)) + "' is not a number (in '" +
                       std::string(text) + "')");
    out.push_back(*v);
  }
  if (count && out.size() != count)
    throw UsageError(option + " needs " + std::to_string(count) + " comma-separated numbers, got " +
                     std::to_string(out.size()) + " in '" + std::string(text) + "'");
  return out;
}

std::vector<Vec3d> parse_point_list(const std::string& option, std::string_view text) {
  std::vector<Vec3d> out;
  if (trim(text).empty()) throw UsageError(option + " is empty");
  for (std::string_view p : split(text, ';')) {
    if (trim(p).empty()) continue;  // a trailing ';'
    const std::vector<double> x = parse_number_list(option, p, 3);
    out.push_back({x[0], x[1], x[2]});
  }
  return out;
}

std::vector<Vec3d> read_points(const std::string& path) {
  if (!(has_suffix(path, ".csv") || has_suffix(path, ".xyz") || has_suffix(path, ".txt") ||
        has_suffix(path, ".pts")))
    return read_mesh(path).vertices;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, {}, "cannot open the file");
  std::vector<Vec3d> out;
  std::string line;
  std::uint64_t number = 0;
  bool header_allowed = true;
  while (std::getline(in, line)) {
    ++number;
    std::string_view l = line;
    if (const auto hash = l.find('#'); hash != std::string_view::npos) l = l.substr(0, hash);
    l = trim(l);
    if (l.empty()) continue;
    std::vector<double> x;
    std::size_t i = 0, bad_column = 0;
    while (i < l.size()) {
      while (i < l.size() &&
             (std::isspace(static_cast<unsigned char>(l[i])) || l[i] == ',' || l[i] == ';'))
        ++i;
      if (i >= l.size()) break;
      std::size_t j = i;
      while (j < l.size() && !std::isspace(static_cast<unsigned char>(l[j])) && l[j] != ',' &&
             l[j] != ';')
        ++j;
      const auto v = number_or_special(l.substr(i, j - i));
      if (!v) {
        bad_column = i + 1;
        break;
      }
      x.push_back(*v);
      i = j;
    }
    InputPosition where;
    where.line = number;
    where.has_line = true;
    if (bad_column) {
      if (header_allowed && out.empty()) {  // one header line ("x,y,z")
        header_allowed = false;
        continue;
      }
      where.column = bad_column;
      throw InputError(path, where, "not a number");
    }
    if (x.size() < 3)
      throw InputError(path, where, "expected three coordinates, got " + std::to_string(x.size()));
    header_allowed = false;
    out.push_back({x[0], x[1], x[2]});
    if (out.size() > (std::size_t{1} << 28)) throw InputError(path, where, "too many points");
  }
  return out;
}

std::string vec_text(const Vec3d& v) {
  return "(" + format_number(v.x + 0.0) + ", " + format_number(v.y + 0.0) + ", " +
         format_number(v.z + 0.0) + ")";  // + 0.0: no "-0"
}

}  // namespace pgamesh::cli
