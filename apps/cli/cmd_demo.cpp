// `pgamesh demo`: carriers of a unit tetrahedron by joins, and their magnitudes (paper Tables 3,
// 4).
#include <cstdio>

#include "commands.hpp"
#include "pgamesh/algebra/pga3.hpp"

namespace pgamesh::cli {

namespace {

int run_demo() {
  using namespace pgamesh::pga3;
  const auto o = origin<double>();
  const auto a = point(1.0, 0.0, 0.0), b = point(0.0, 1.0, 0.0), c = point(0.0, 0.0, 1.0);
  const Line<double> edge = a & b;
  const Plane<double> face = a & b & c;
  std::printf("vertices a=(1,0,0) b=(0,1,0) c=(0,0,1), origin o\n");
  std::printf("edge a v b: length |a v b| = %.17g (sqrt 2)\n", norm(edge));
  std::printf("face a v b v c: area |F|/2 = %.17g (sqrt 3 / 2)\n", norm(face) / 2);
  std::printf("tetra o v a v b v c: volume (o v F)/6 = %.17g (1/6)\n", (o & face) / 6);
  return 0;
}

}  // namespace

void add_demo_command(CLI::App& app) {
  CLI::App* sub = add_command(
      app, "demo", "a short PGA demonstration: carriers of a tetrahedron and their magnitudes",
      "Joins the vertices of the unit tetrahedron into the carriers of an edge, a face and the\n"
      "solid, and prints their magnitudes: length, area and volume.");
  on_run(*sub, [] { return run_demo(); });
}

}  // namespace pgamesh::cli
