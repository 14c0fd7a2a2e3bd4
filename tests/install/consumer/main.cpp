// The library example of README.md, word for word (tests/install/run.sh checks that they agree).
#include <cstdio>

#include "pgamesh/pgamesh.hpp"

int main(int argc, char** argv) {
  if (argc != 2) return 2;
  // The front door: reads the file with the fastest strategy for its format (a binary STL is
  // streamed, never stored) and gives mass properties, topology and what the reader found.
  const pgamesh::Analysis a = pgamesh::analyze_file(argv[1]);  // throws pgamesh::InputError
  std::printf("volume %.17g, closed %d, centre of mass %g %g %g\n", a.mass.volume,
              a.topology->closed, a.mass.center_of_mass.x, a.mass.center_of_mass.y,
              a.mass.center_of_mass.z);
  if (!a.volume_valid.value_or(false))
    for (const auto& reason : a.reasons) std::printf("not a solid: %s\n", reason.c_str());

  // The algebra underneath: the carrier of a triangle is the join of its vertices, its norm is
  // twice the area.
  using namespace pgamesh::pga3;
  const auto carrier = point(1.0, 0.0, 0.0) & point(0.0, 1.0, 0.0) & point(0.0, 0.0, 1.0);
  std::printf("area %.17g\n", norm(carrier) / 2);
}
