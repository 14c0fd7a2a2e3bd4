// Length units: what a file says its coordinates are in (3MF's `unit`, glTF's metres) or what the
// user states with --unit for files that carry none. Results are given in the file's unit; the
// robot-description exports convert to SI with metres_per_unit (docs/formats.md, "Units").
#pragma once

#include <optional>
#include <string_view>

namespace pgamesh {

enum class LengthUnit { unspecified, micron, millimeter, centimeter, inch, foot, meter };

// Metres in one unit; exact decimal factors (an inch is 0.0254 m by definition;
// docs/conventions.md §14). 1 for `unspecified`, whose figures are unitless.
constexpr double metres_per_unit(LengthUnit u) {
  switch (u) {
    case LengthUnit::micron:
      return 1e-6;
    case LengthUnit::millimeter:
      return 1e-3;
    case LengthUnit::centimeter:
      return 1e-2;
    case LengthUnit::inch:
      return 0.0254;
    case LengthUnit::foot:
      return 0.3048;
    case LengthUnit::meter:
    case LengthUnit::unspecified:
      break;
  }
  return 1.0;
}

// The short name printed in outputs and accepted by --unit: "um", "mm", "cm", "in", "ft", "m";
// "unitless" for `unspecified`.
constexpr const char* unit_name(LengthUnit u) {
  switch (u) {
    case LengthUnit::micron:
      return "um";
    case LengthUnit::millimeter:
      return "mm";
    case LengthUnit::centimeter:
      return "cm";
    case LengthUnit::inch:
      return "in";
    case LengthUnit::foot:
      return "ft";
    case LengthUnit::meter:
      return "m";
    case LengthUnit::unspecified:
      break;
  }
  return "unitless";
}

// The unit a name stands for: the short names above and 3MF's spelled-out names ("micron",
// "millimeter", "centimeter", "inch", "foot", "meter"); nullopt otherwise.
constexpr std::optional<LengthUnit> unit_from_name(std::string_view name) {
  if (name == "um" || name == "micron") return LengthUnit::micron;
  if (name == "mm" || name == "millimeter") return LengthUnit::millimeter;
  if (name == "cm" || name == "centimeter") return LengthUnit::centimeter;
  if (name == "in" || name == "inch") return LengthUnit::inch;
  if (name == "ft" || name == "foot") return LengthUnit::foot;
  if (name == "m" || name == "meter") return LengthUnit::meter;
  return std::nullopt;
}

}  // namespace pgamesh
