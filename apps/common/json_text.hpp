// The JSON documents of the CLI (`--json` of props, check, fuel) and of the viewer's server: built
// as nlohmann::ordered_json (fields stay in the order they are written: the stable fields first),
// printed by json_text() on one line with every floating-point number as %.17g
// (pgamesh/core/number_text.hpp), the text the project prints everywhere — CSV, text reports and
// JSON show the same digits, and each reads back to the same bits. Field definitions: docs/json.md.
//
// One rule for undefined values: a number that is not finite, and a vector, matrix or object of
// numbers with any entry not finite, is written as a whole as null (never [null, null, null]).
#pragma once

#include <array>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "pgamesh/algebra/pga3.hpp"
#include "pgamesh/core/vec3.hpp"

namespace pgamesh::cli {

using Json = nlohmann::ordered_json;

// The document as one line of JSON: numbers %.17g, non-finite numbers null, strings escaped (bytes
// that are not UTF-8 become U+FFFD).
std::string json_text(const Json& document);

// A number, or null when it is not finite.
Json json_number(double v);
// [low, high], or null unless both are finite.
Json json_range(double low, double high);
// [x, y, z], or null unless all three are finite.
Json json_vec3(const Vec3d& v);
// A 3×3 matrix as an array of its rows, or null unless all nine entries are finite.
Json json_matrix3(const std::array<std::array<double, 3>, 3>& m);
// A PGA3 plane (or a sum of face carriers) as {"e0", "e1", "e2", "e3"}, or null unless finite.
Json json_plane(const pga3::Plane<double>& p);
// An array of strings (warnings, reasons, notes).
Json json_strings(const std::vector<std::string>& list);

}  // namespace pgamesh::cli
