#include "mesh/mass/stl_mass_properties.hpp"

#include <cmath>

#include "detail/memory/page_release.hpp"
#include "geometry/chunked_sums.hpp"
#include "io/stl_record_blocks.hpp"

namespace pgamesh {

namespace {

// The bounding box of evenly spaced records: cheap, deterministic, and close enough to the whole
// box for placing the reference point and judging float32 precision. With `release_records`, the
// sampled pages are given back as the samples pass (a fault maps a whole folio of the page cache
// around each sample, so the samples of a large file would otherwise map all of it). With a file
// (BinaryStlView::file), each sample is read on its own. L is the view's layout.
template <TriangleRecordLayout L>
Box3 sampled_box(const BinaryStlView& view, const std::string& name, bool release_records) {
  Box3 box;
  const std::uint64_t step = std::max<std::uint64_t>(1, view.count / stl_reference_samples);
  detail::PageRelease release(view.records, release_records);
  for (std::uint64_t i = 0; i < view.count; i += step) {
    release.passed(view.records + L.stride * i);
    Vec3d v[3];
    stl_triangle<L>(detail::record_block(view, i, 1, name), v);
    for (const Vec3d& p : v)
      if (is_finite(p)) box.add(p);
  }
  return box;
}

bool finite(const BoundarySums& s) {
  return std::isfinite(s.area2) && std::isfinite(s.volume6) && std::isfinite(s.moment24.x) &&
         std::isfinite(s.moment24.y) && std::isfinite(s.moment24.z) &&
         std::isfinite(s.second120[0]) && std::isfinite(s.second120[1]) &&
         std::isfinite(s.second120[2]);
}

// Adds the records [begin, end) of the view (begin a multiple of sum_lanes), record f to lanes[f]
// as add_triangle does: four records at a time in Double4 lanes, which give the same bits, the
// last few one by one. The blocks of records_per_block (a multiple of sum_lanes) keep the lanes'
// order. L is the view's layout. Flattened: with a pass per layout, the compiler would otherwise
// call add_triangle out of line from each (the STL's pass on 10^7 triangles 13 % slower).
template <TriangleRecordLayout L>
[[gnu::flatten]] void add_records(LanedSums<>& lanes, const BinaryStlView& view, std::size_t begin,
                                  std::size_t end, Vec3d ref, const std::string& name) {
  static_assert(detail::records_per_block % sum_lanes == 0);
  const Vec3<Double4> ref4{ref.x, ref.y, ref.z};
  BasicBoundarySums<Double4> four;
  const std::size_t whole = begin + (end - begin) / sum_lanes * sum_lanes;
  detail::for_record_blocks(view, begin, whole, name,
                            [&](const unsigned char* r, std::uint64_t b, std::uint64_t e) {
                              for (; b < e; b += sum_lanes, r += sum_lanes * L.stride) {
                                Vec3<Double4> v[3];
                                stl_triangles4<L>(r, v);
                                add_triangle(four, v[0] - ref4, v[1] - ref4, v[2] - ref4);
                              }
                            });
  set_lanes(lanes, four);
  detail::for_record_blocks(view, whole, end, name,
                            [&](const unsigned char* r, std::uint64_t b, std::uint64_t e) {
                              for (; b < e; ++b, r += L.stride) {
                                Vec3d v[3];
                                stl_triangle<L>(r, v);
                                add_triangle(lanes[b], v[0] - ref, v[1] - ref, v[2] - ref);
                              }
                            });
}

template <TriangleRecordLayout L>
MassProperties record_mass_properties(const BinaryStlView& view, const std::string& name,
                                      const MassOptions& options, bool release_records) {
  const bool release = detail::releases_mapped_records(view, release_records);
  const Box3 box = sampled_box<L>(view, name, release);
  const unsigned char* records_end = view.records + L.stride * view.count;
  if (release) detail::release_pages(view.records, records_end);
  const Vec3d ref = box.centre();
  const BoundarySums total = chunked_sums(
      view.count, options.threads, [&](LanedSums<>& lanes, std::size_t begin, std::size_t end) {
        add_records<L>(lanes, view, begin, end, ref, name);
        if (release)
          detail::release_pages(view.records + L.stride * begin, view.records + L.stride * end);
      });
  if (release) detail::release_pages(view.records, records_end);  // chunks' shared pages
  // A NaN or infinity anywhere poisons the sums: name the first culprit (throws).
  if (!finite(total)) check_binary_stl_finite(view, name);
  MassProperties p = mass_properties_from_sums(total, ref, options);
  p.faces = p.triangles = view.count;
  p.vertices = 3 * view.count;
  if (auto w = float32_precision_warning(box)) p.warnings.push_back(*w);
  return p;
}

}  // namespace

MassProperties binary_stl_mass_properties(const BinaryStlView& view, const std::string& name,
                                          const MassOptions& options, bool release_records) {
  return with_record_layout(view.layout, [&](auto layout) {
    return record_mass_properties<decltype(layout)::layout>(view, name, options, release_records);
  });
}

}  // namespace pgamesh
