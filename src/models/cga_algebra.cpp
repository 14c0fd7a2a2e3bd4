// Blade keys of the null basis e_o, e1, e2, e3, e_∞ in the golden files' spelling
// (docs/models-cga.md §1).
#include "pgamesh/models/cga_algebra.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace pgamesh::cga {

namespace {

constexpr std::array<const char*, 5> factor_names = {"eo", "e1", "e2", "e3", "einf"};

}  // namespace

std::string blade_key(BladeMask mask) {
  if (mask == 0) return "1";
  std::string s;
  for (int i = 0; i < 5; ++i)
    if (mask >> i & 1u) {
      if (!s.empty()) s += '^';
      s += factor_names[static_cast<std::size_t>(i)];
    }
  return s;
}

BladeMask parse_blade_key(const std::string& key) {
  if (key == "1") return 0;
  BladeMask mask = 0;
  int last = -1;
  std::size_t pos = 0;
  while (pos <= key.size()) {
    const std::size_t end = std::min(key.find('^', pos), key.size());
    const std::string f = key.substr(pos, end - pos);
    int idx = -1;
    for (int i = 0; i < 5; ++i)
      if (f == factor_names[static_cast<std::size_t>(i)]) idx = i;
    if (f == "ei") idx = 4;
    if (idx < 0) throw ModelError("cga: '" + key + "' is not a blade key (factor '" + f + "')");
    if (idx <= last)
      throw ModelError("cga: blade key '" + key +
                       "' must list its factors once each in the order eo, e1, e2, e3, einf");
    last = idx;
    mask |= BladeMask{1} << idx;
    pos = end + 1;
  }
  return mask;
}

const std::array<BladeMask, 32>& listing_order() {
  static const std::array<BladeMask, 32> order = [] {
    std::array<BladeMask, 32> out{};
    for (BladeMask m = 0; m < 32; ++m) out[m] = m;
    // By grade, then lexicographic in the factor indices: compare the bit-reversed masks (the
    // lowest factor first) in descending order.
    auto rev = [](BladeMask m) {
      BladeMask r = 0;
      for (int i = 0; i < 5; ++i)
        if (m >> i & 1u) r |= BladeMask{1} << (4 - i);
      return r;
    };
    std::sort(out.begin(), out.end(), [&](BladeMask a, BladeMask b) {
      const int ga = clifford::grade_of(a), gb = clifford::grade_of(b);
      if (ga != gb) return ga < gb;
      return rev(a) > rev(b);
    });
    return out;
  }();
  return order;
}

std::vector<std::pair<std::string, double>> named_blades(const std::array<double, 32>& coeffs,
                                                         double rel) {
  double scale = 0;
  for (double c : coeffs) scale = std::max(scale, std::abs(c));
  std::vector<std::pair<std::string, double>> out;
  for (BladeMask m : listing_order()) {
    const double c = coeffs[m];
    if (c != 0 && !(std::abs(c) <= rel * scale)) out.emplace_back(blade_key(m), c);
  }
  return out;
}

Full from_named_full(const std::vector<std::pair<std::string, double>>& named) {
  Full out;
  for (const auto& [key, c] : named)
    out.c[static_cast<std::size_t>(Full::index_of(parse_blade_key(key)))] += c;
  return out;
}

std::string to_string(const std::array<double, 32>& coeffs) {
  std::ostringstream s;
  s.precision(17);
  bool any = false;
  for (const auto& [key, c] : named_blades(coeffs)) {
    if (any)
      s << (c < 0 ? " - " : " + ");
    else if (c < 0)
      s << '-';
    s << std::abs(c);
    if (key != "1") s << ' ' << key;
    any = true;
  }
  if (!any) s << '0';
  return s.str();
}

}  // namespace pgamesh::cga
