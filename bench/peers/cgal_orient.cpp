// Peer for bench/compare_orientation.sh: CGAL's PMP::orient_to_bound_a_volume on a mesh file, the
// anchor for pgamesh's orientation by nesting (docs/conventions.md §8). Prints the signed volume
// before and after, and the signed volume of each connected component after, in the order of
// their lowest face.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/IO/polygon_mesh_io.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Surface_mesh.h>

#include <cstdio>
#include <map>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: cgal_orient FILE\n");
    return 2;
  }
  SurfaceMesh mesh;
  if (!PMP::IO::read_polygon_mesh(argv[1], mesh) || mesh.is_empty()) {
    std::fprintf(stderr, "cgal_orient: cannot read %s\n", argv[1]);
    return 1;
  }
  const double before = CGAL::to_double(PMP::volume(mesh));
  PMP::orient_to_bound_a_volume(mesh);
  const double after = CGAL::to_double(PMP::volume(mesh));
  std::printf("volume_before %.17g volume_after %.17g components", before, after);

  // Σ of the faces' signed tetrahedra about the origin, per component (faces in index order).
  auto component = mesh.add_property_map<SurfaceMesh::Face_index, std::size_t>("f:cc", 0).first;
  const std::size_t count = PMP::connected_components(mesh, component);
  std::vector<double> volume(count, 0.0);
  std::vector<std::size_t> order;
  std::vector<bool> seen(count, false);
  for (SurfaceMesh::Face_index f : mesh.faces()) {
    const std::size_t k = component[f];
    if (!seen[k]) {
      seen[k] = true;
      order.push_back(k);
    }
    auto h = mesh.halfedge(f);
    const auto& a = mesh.point(mesh.source(h));
    for (auto g = mesh.next(h); mesh.target(g) != mesh.source(h); g = mesh.next(g)) {
      const auto& b = mesh.point(mesh.source(g));
      const auto& c = mesh.point(mesh.target(g));
      volume[k] +=
          CGAL::to_double(CGAL::determinant(a - CGAL::ORIGIN, b - CGAL::ORIGIN, c - CGAL::ORIGIN)) /
          6;
    }
  }
  for (std::size_t k : order) std::printf(" %.17g", volume[k]);
  std::printf("\n");
  return 0;
}
