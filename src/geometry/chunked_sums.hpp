// Deterministic parallel accumulation of boundary sums. The faces are cut into chunks of a fixed
// size (independent of the thread count). Within a chunk, face i goes to lane i mod 4, each lane
// summed on its own in face order; the chunk's sum is (lane 0 + lane 1) + (lane 2 + lane 3), and
// the chunk sums are added in chunk order. The result is therefore the same bit for bit with 1, 2
// or 64 threads (docs/conventions.md §13: results do not depend on the thread count), and the same
// whether the lanes are summed one face at a time or four at once (Double4, algebra/double4.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

#include "detail/simd/double4.hpp"
#include "pgamesh/geometry/body_moments.hpp"

namespace pgamesh {

// Faces per chunk: large enough that a chunk costs far more than starting it, small enough that
// two threads share a mesh of a few hundred thousand faces evenly. A multiple of sum_lanes, so a
// face's lane is its index mod sum_lanes.
inline constexpr std::size_t faces_per_chunk = std::size_t{1} << 14;

// Lanes per chunk: independent running sums, which four faces can add at once.
inline constexpr std::size_t sum_lanes = 4;
static_assert(faces_per_chunk % sum_lanes == 0);

// The running sums of one chunk, one per lane.
template <class Partial = BoundarySums>
struct LanedSums {
  std::array<Partial, sum_lanes> lane{};

  // The running sums that face number `face` (of the mesh, or of the chunk) adds to.
  Partial& operator[](std::size_t face) { return lane[face % sum_lanes]; }

  // The chunk's sum: (lane 0 + lane 1) + (lane 2 + lane 3).
  Partial total() const {
    Partial low = lane[0], high = lane[2];
    low += lane[1];
    high += lane[3];
    low += high;
    return low;
  }
};

// Lane j of sums of four faces side by side: the sums, in double, of the faces of lane j.
inline BoundarySums lane(const BasicBoundarySums<Double4>& s, int j) {
  BoundarySums out;
  out.area2 = s.area2.lane(j);
  out.carrier_sum = {s.carrier_sum.e0.lane(j), s.carrier_sum.e1.lane(j), s.carrier_sum.e2.lane(j),
                     s.carrier_sum.e3.lane(j)};
  out.volume6 = s.volume6.lane(j);
  out.moment24 = {s.moment24.x.lane(j), s.moment24.y.lane(j), s.moment24.z.lane(j)};
  for (int i = 0; i < 6; ++i) out.second120[i] = s.second120[i].lane(j);
  return out;
}

// Sets the lanes of a chunk to the sums of its first faces summed four at a time (lane j of `four`
// holding faces j, j + 4, …), before its last few faces are added one by one.
inline void set_lanes(LanedSums<>& lanes, const BasicBoundarySums<Double4>& four) {
  for (std::size_t j = 0; j < sum_lanes; ++j) lanes.lane[j] = lane(four, static_cast<int>(j));
}

// The number of threads to use when the caller asks for 0 ("all"): the hardware concurrency.
inline unsigned resolve_threads(unsigned requested) {
  if (requested) return requested;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw ? hw : 1;
}

// Σ over faces [0, count) of what add_range(lanes, begin, end) accumulates for the faces
// [begin, end), face f into lanes[f], computed on up to `threads` threads (0 = all) with the fixed
// chunking above. Partial is BoundarySums or any value-initialisable type with +=. add_range must
// not throw.
template <class Partial = BoundarySums, class AddRange>
Partial chunked_sums(std::size_t count, unsigned threads, const AddRange& add_range) {
  const std::size_t chunks = (count + faces_per_chunk - 1) / faces_per_chunk;
  std::vector<Partial> partial(chunks);
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t k; (k = next.fetch_add(1, std::memory_order_relaxed)) < chunks;) {
      const std::size_t begin = k * faces_per_chunk;
      // Summed in a local, not in place: neighbouring partials share a cache line, which two
      // threads writing face by face would pass back and forth.
      LanedSums<Partial> lanes;
      add_range(lanes, begin, std::min(count, begin + faces_per_chunk));
      partial[k] = lanes.total();
    }
  };
  const std::size_t workers = std::min<std::size_t>(resolve_threads(threads), chunks);
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < workers; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  Partial total{};
  for (const Partial& p : partial) total += p;
  return total;
}

// The same sums as chunked_sums for faces handed over one at a time in face order, on one thread
// (a reader that sums each face as it parses it and keeps no face list): each chunk of
// faces_per_chunk faces is summed in its lanes from value-initialised partials, and the chunk sums
// are added in chunk order, so total() is chunked_sums' result bit for bit.
template <class Partial = BoundarySums>
class StreamedChunkSums {
 public:
  // The running sums that the next face adds to; call next() after adding it.
  Partial& current() { return lanes_[in_chunk_]; }

  // The face just added to current() is done.
  void next() {
    if (++in_chunk_ == faces_per_chunk) flush();
  }

  // The sums of every face added so far.
  Partial total() const {
    Partial t = total_;
    if (in_chunk_ > 0) t += lanes_.total();
    return t;
  }

 private:
  void flush() {
    total_ += lanes_.total();
    lanes_ = LanedSums<Partial>{};
    in_chunk_ = 0;
  }

  Partial total_{};
  LanedSums<Partial> lanes_;
  std::size_t in_chunk_ = 0;
};

}  // namespace pgamesh
