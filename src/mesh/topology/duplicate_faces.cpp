#include "mesh/topology/duplicate_faces.hpp"

#include <limits>

namespace pgamesh::detail {

std::vector<std::pair<std::uint32_t, std::uint32_t>> duplicated_faces(const SameVertexRuns& runs) {
  // Every run's members after its first (the first has no face below it in the run), by face.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> order;  // (face, run)
  for (std::size_t r = 0; r < runs.ends.size(); ++r)
    for (std::size_t i = runs.begin_of(r) + 1; i < runs.ends[r]; ++i)
      order.emplace_back(runs.members[i].face, static_cast<std::uint32_t>(r));
  std::sort(order.begin(), order.end());

  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;  // ascending by face
  auto duplicated = [&](std::uint32_t f) {
    return std::binary_search(out.begin(), out.end(), std::pair{f, std::uint32_t{0}},
                              [](const auto& a, const auto& b) { return a.first < b.first; });
  };
  // Per run, the member that is its lowest first-side face not duplicated, once the faces before
  // the one being judged are settled. Every face below the one judged is settled (faces are judged
  // in order), so the cursor only moves on, and it stops at the judged face's own member at the
  // latest.
  std::vector<std::size_t> lowest(runs.ends.size());
  for (std::size_t r = 0; r < lowest.size(); ++r) lowest[r] = runs.begin_of(r);
  constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  for (std::size_t i = 0; i < order.size();) {
    const std::uint32_t g = order[i].first;
    std::uint32_t same_as = none;
    for (; i < order.size() && order[i].first == g; ++i) {
      std::size_t& c = lowest[order[i].second];
      while (runs.members[c].face < g &&
             (!runs.members[c].first_side_here || duplicated(runs.members[c].face)))
        ++c;
      if (runs.members[c].face < g) same_as = std::min(same_as, runs.members[c].face);
    }
    if (same_as != none) out.emplace_back(g, same_as);
  }
  return out;
}

}  // namespace pgamesh::detail
