// Readable and JSON printing of `pgamesh calc` values.
#include "calc_print.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <vector>

namespace pgamesh::cli {

namespace {

std::vector<clifford::Term> display_terms(const clifford::Algebra& a,
                                          const clifford::Multivector& m) {
  std::vector<clifford::Term> t = m.terms;
  std::stable_sort(t.begin(), t.end(), [&a](const clifford::Term& x, const clifford::Term& y) {
    return a.display_before(x.mask, y.mask);
  });
  return t;
}

std::string digits_of(double v, int digits) {
  if (v == 0) return "0";
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, digits);
  return std::string(buf, r.ptr);
}

}  // namespace

std::string format_text(const clifford::Algebra& algebra, const clifford::Multivector& m,
                        const TextFormat& format) {
  const double largest = clifford::max_abs_coeff(m);
  std::string out;
  for (const auto& t : display_terms(algebra, m)) {
    if (std::isfinite(largest) && std::abs(t.coeff) < format.hide_below * largest) continue;
    const auto [name, sign] = algebra.blade_name(t.mask);
    const double c = sign * t.coeff;
    const bool negative = std::signbit(c);
    if (out.empty()) {
      if (negative) out += "-";
    } else {
      out += negative ? " - " : " + ";
    }
    const std::string number = digits_of(std::abs(c), format.digits);
    if (t.mask == 0)
      out += number;
    else
      out += (number == "1" ? "" : number + " ") + name;
  }
  return out.empty() ? "0" : out;
}

Json format_json(const clifford::Algebra& algebra, const clifford::Multivector& m) {
  Json out = Json::object();
  for (const auto& t : display_terms(algebra, m)) {
    const auto [name, sign] = algebra.blade_name(t.mask);
    out[name] = json_number(sign * t.coeff);
  }
  return out;
}

}  // namespace pgamesh::cli
