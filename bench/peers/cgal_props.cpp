// Peer for bench/compare_peers.sh: CGAL's Polygon Mesh Processing volume, area and centroid of a
// mesh file (STL, OBJ, PLY, OFF via PMP::IO::read_polygon_mesh, which also repairs the soup).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Surface_mesh.h>

#include <cstdio>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: cgal_props FILE\n");
    return 2;
  }
  SurfaceMesh mesh;
  if (!PMP::IO::read_polygon_mesh(argv[1], mesh) || mesh.is_empty()) {
    std::fprintf(stderr, "cgal_props: cannot read %s\n", argv[1]);
    return 1;
  }
  const double volume = CGAL::to_double(PMP::volume(mesh));
  const double area = CGAL::to_double(PMP::area(mesh));
  const auto c = PMP::centroid(mesh);
  std::printf("faces %zu volume %.17g area %.17g centroid %.17g %.17g %.17g\n",
              static_cast<std::size_t>(mesh.number_of_faces()), volume, area,
              CGAL::to_double(c.x()), CGAL::to_double(c.y()), CGAL::to_double(c.z()));
  return 0;
}
