// Peer for bench/compare_self_intersections.sh: CGAL's Polygon_mesh_processing::self_intersections
// on a triangle mesh file, the anchor for pgamesh's self-intersection pass (docs/topology.md,
// "Self-intersections"). The file is read as a polygon soup and its bitwise-equal points merged
// (pgamesh's exact weld); a soup that is not a manifold mesh is oriented first, which gives every
// non-manifold vertex one copy per fan (pgamesh keeps them welded: see the docs). Prints the
// intersecting pairs of distinct faces, the degenerate faces (CGAL reports each as a pair (f, f)
// and leaves it out of the other tests) and the seconds the call took; with --pairs, every pair.
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <iterator>
#include <utility>
#include <vector>

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Kernel::Point_3;
using SurfaceMesh = CGAL::Surface_mesh<Point>;
namespace PMP = CGAL::Polygon_mesh_processing;

int main(int argc, char** argv) {
  const bool list = argc == 3 && std::strcmp(argv[2], "--pairs") == 0;
  if (argc != 2 && !list) {
    std::fprintf(stderr, "usage: cgal_self_intersections FILE [--pairs]\n");
    return 2;
  }
  std::vector<Point> points;
  std::vector<std::vector<std::size_t>> polygons;
  if (!CGAL::IO::read_polygon_soup(argv[1], points, polygons) || polygons.empty()) {
    std::fprintf(stderr, "cgal_self_intersections: cannot read %s\n", argv[1]);
    return 1;
  }
  for (const auto& p : polygons)
    if (p.size() != 3) {
      std::fprintf(stderr, "cgal_self_intersections: %s has a face that is not a triangle\n",
                   argv[1]);
      return 1;
    }
  PMP::merge_duplicate_points_in_polygon_soup(points, polygons);
  bool oriented = false;
  if (!PMP::is_polygon_soup_a_polygon_mesh(polygons)) {
    PMP::orient_polygon_soup(points, polygons);
    oriented = true;
  }
  SurfaceMesh mesh;
  PMP::polygon_soup_to_polygon_mesh(points, polygons, mesh);

  using Face = SurfaceMesh::Face_index;
  std::vector<std::pair<Face, Face>> found;
  const auto start = std::chrono::steady_clock::now();
  PMP::self_intersections(mesh, std::back_inserter(found));
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::vector<std::pair<std::size_t, std::size_t>> pairs;
  std::size_t degenerate = 0;
  for (const auto& [f, g] : found) {
    if (f == g) {
      ++degenerate;
      continue;
    }
    pairs.emplace_back(std::min<std::size_t>(f, g), std::max<std::size_t>(f, g));
  }
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  std::printf("pairs %zu degenerate %zu faces %zu seconds %.3f%s\n", pairs.size(), degenerate,
              static_cast<std::size_t>(mesh.number_of_faces()), seconds,
              oriented ? " (not a manifold soup: oriented, non-manifold vertices split)" : "");
  if (list)
    for (const auto& [f, g] : pairs) std::printf("%zu %zu\n", f, g);
  return 0;
}
