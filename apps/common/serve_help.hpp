// The usage of `pgamesh serve`, printed by the command (apps/cli/cmd_serve.cpp) even in a build
// without the viewer, and by the server executable (apps/viewer/main.cpp) on a bad option.
#pragma once

#include <cstdio>

namespace pgamesh::cli {

// Prints the usage and options of `pgamesh serve` on `out`.
void print_serve_help(std::FILE* out);

}  // namespace pgamesh::cli
