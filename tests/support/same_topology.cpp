#include "same_topology.hpp"

namespace pgamesh::test {

void expect_same_faces(const std::vector<FaceLocation>& a, const std::vector<FaceLocation>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].face, b[i].face);
    EXPECT_EQ(a[i].same_as, b[i].same_as);
    EXPECT_SAME(a[i].area, b[i].area);
    EXPECT_SAME_VEC(a[i].centroid, b[i].centroid);
  }
}

void expect_same_edges(const std::vector<EdgeLocation>& a, const std::vector<EdgeLocation>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].face, b[i].face);
    EXPECT_EQ(a[i].vertex0, b[i].vertex0);
    EXPECT_EQ(a[i].vertex1, b[i].vertex1);
    EXPECT_EQ(a[i].face_count, b[i].face_count);
    EXPECT_SAME_VEC(a[i].p0, b[i].p0);
    EXPECT_SAME_VEC(a[i].p1, b[i].p1);
  }
}

void expect_same_report(const TopologyReport& a, const TopologyReport& b) {
  EXPECT_EQ(a.faces, b.faces);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.input_vertices, b.input_vertices);
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_EQ(a.merged_vertices, b.merged_vertices);
  EXPECT_EQ(a.unreferenced_vertices, b.unreferenced_vertices);
  EXPECT_SAME(a.weld_tolerance, b.weld_tolerance);
  EXPECT_SAME(a.weld_max_moved, b.weld_max_moved);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.boundary_edges, b.boundary_edges);
  EXPECT_EQ(a.nonmanifold_edges, b.nonmanifold_edges);
  EXPECT_EQ(a.inconsistent_edges, b.inconsistent_edges);
  EXPECT_EQ(a.closed, b.closed);
  EXPECT_EQ(a.orientation_consistent, b.orientation_consistent);
  EXPECT_SAME_VEC(a.reference_point, b.reference_point);
  EXPECT_SAME(a.area, b.area);
  EXPECT_SAME(a.volume, b.volume);
  EXPECT_SAME(a.carrier_sum.e0, b.carrier_sum.e0);
  EXPECT_SAME_VEC(a.carrier_sum.normal(), b.carrier_sum.normal());
  EXPECT_SAME_VEC(a.gap_vector, b.gap_vector);
  EXPECT_SAME(a.gap_area, b.gap_area);
  EXPECT_SAME(a.volume_min, b.volume_min);
  EXPECT_SAME(a.volume_max, b.volume_max);
  EXPECT_SAME(a.loops_area, b.loops_area);
  ASSERT_EQ(a.boundary_loops.size(), b.boundary_loops.size());
  for (std::size_t i = 0; i < a.boundary_loops.size(); ++i) {
    const BoundaryLoop &x = a.boundary_loops[i], &y = b.boundary_loops[i];
    EXPECT_EQ(x.half_edges, y.half_edges);
    EXPECT_EQ(x.closed, y.closed);
    EXPECT_SAME_VEC(x.vector_area, y.vector_area);
    EXPECT_SAME(x.area, y.area);
    EXPECT_SAME(x.perimeter, y.perimeter);
  }
  EXPECT_EQ(a.zero_area_faces, b.zero_area_faces);
  EXPECT_EQ(a.collapsed_faces, b.collapsed_faces);
  EXPECT_EQ(a.small_area_faces, b.small_area_faces);
  EXPECT_EQ(a.duplicated_faces, b.duplicated_faces);
  EXPECT_EQ(a.duplicated_area_faces, b.duplicated_area_faces);
  EXPECT_SAME(a.area_threshold, b.area_threshold);
  expect_same_faces(a.zero_area_list, b.zero_area_list);
  expect_same_faces(a.small_area_list, b.small_area_list);
  expect_same_faces(a.duplicated_list, b.duplicated_list);
  expect_same_edges(a.boundary_edge_list, b.boundary_edge_list);
  expect_same_edges(a.nonmanifold_edge_list, b.nonmanifold_edge_list);
  expect_same_edges(a.inconsistent_edge_list, b.inconsistent_edge_list);
  EXPECT_EQ(a.components, b.components);
  EXPECT_EQ(a.closed_components, b.closed_components);
  EXPECT_EQ(a.cavity_components, b.cavity_components);
  EXPECT_EQ(a.inward_components, b.inward_components);
  ASSERT_EQ(a.component_list.size(), b.component_list.size());
  for (std::size_t i = 0; i < a.component_list.size(); ++i) {
    const ComponentSummary &x = a.component_list[i], &y = b.component_list[i];
    EXPECT_EQ(x.first_face, y.first_face);
    EXPECT_EQ(x.faces, y.faces);
    EXPECT_SAME(x.area, y.area);
    EXPECT_SAME(x.volume, y.volume);
    EXPECT_EQ(x.boundary_edges, y.boundary_edges);
    EXPECT_EQ(x.nonmanifold_edges, y.nonmanifold_edges);
    EXPECT_EQ(x.inconsistent_edges, y.inconsistent_edges);
    EXPECT_EQ(x.closed, y.closed);
    EXPECT_EQ(x.depth, y.depth);
    EXPECT_EQ(x.cavity, y.cavity);
    EXPECT_EQ(x.inward, y.inward);
  }
  EXPECT_EQ(a.self_intersections_checked, b.self_intersections_checked);
  EXPECT_EQ(a.self_intersecting_pairs, b.self_intersecting_pairs);
  EXPECT_EQ(a.self_intersections_complete, b.self_intersections_complete);
  ASSERT_EQ(a.self_intersection_list.size(), b.self_intersection_list.size());
  for (std::size_t i = 0; i < a.self_intersection_list.size(); ++i) {
    const SelfIntersection &x = a.self_intersection_list[i], &y = b.self_intersection_list[i];
    EXPECT_EQ(x.face0, y.face0);
    EXPECT_EQ(x.face1, y.face1);
    EXPECT_SAME(x.point.x, y.point.x);
    EXPECT_SAME(x.point.y, y.point.y);
    EXPECT_SAME(x.point.z, y.point.z);
  }
  EXPECT_EQ(a.volume_valid, b.volume_valid);
  EXPECT_EQ(a.notes, b.notes);
}

void expect_same_mass(const MassProperties& a, const MassProperties& b) {
  EXPECT_EQ(a.faces, b.faces);
  EXPECT_EQ(a.triangles, b.triangles);
  EXPECT_EQ(a.vertices, b.vertices);
  EXPECT_SAME_VEC(a.reference_point, b.reference_point);
  EXPECT_SAME_VEC(a.center_of_mass, b.center_of_mass);
  for (int k = 0; k < 3; ++k) {
    EXPECT_SAME(a.principal.moments[k], b.principal.moments[k]);
    for (int j = 0; j < 3; ++j) {
      EXPECT_SAME(a.inertia_com[k][j], b.inertia_com[k][j]);
      EXPECT_SAME(a.inertia_origin[k][j], b.inertia_origin[k][j]);
    }
  }
  EXPECT_SAME(a.area, b.area);
  EXPECT_SAME(a.volume, b.volume);
  EXPECT_SAME(a.mass, b.mass);
  EXPECT_SAME(a.density, b.density);
  EXPECT_SAME(a.gap_area, b.gap_area);
  EXPECT_SAME(a.carrier_sum.e0, b.carrier_sum.e0);
  EXPECT_SAME_VEC(a.carrier_sum.normal(), b.carrier_sum.normal());
  EXPECT_EQ(a.warnings, b.warnings);
}

}  // namespace pgamesh::test
