// What the model commands (`pgamesh cga`, `quadric`, `fit`; docs/models.md) share: point lists
// as text, point files, and the readable printing of vectors.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "pgamesh/core/vec3.hpp"

namespace pgamesh::cli {

// "x,y,z;x,y,z;…" as points. Throws UsageError (exit 2) for text that is not numbers in groups of
// three; NaN and infinities ("nan", "inf") are read as such, for the models to refuse (exit 1).
std::vector<Vec3d> parse_point_list(const std::string& option, std::string_view text);
// "a,b,c,…" as exactly `count` numbers (NaN and infinities read as such). Throws UsageError.
std::vector<double> parse_number_list(const std::string& option, std::string_view text,
                                      std::size_t count);

// The points of a file: a CSV or XYZ point file (.csv, .xyz, .txt, .pts: three numbers a line,
// separated by commas, semicolons or blanks; '#' comments, blank lines and one header line
// allowed), else a mesh read by read_mesh (its vertices). Throws InputError naming the file and
// the line.
std::vector<Vec3d> read_points(const std::string& path);

// "(x, y, z)" with %.17g.
std::string vec_text(const Vec3d& v);

}  // namespace pgamesh::cli
