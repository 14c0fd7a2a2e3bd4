// Deterministic parallel accumulation of boundary sums. The faces are cut into chunks of a fixed
// size (independent of the thread count); each chunk is summed on its own, in face order, and the
// chunk sums are added in chunk order. The result is therefore the same bit for bit with 1, 2 or 64
// threads (DESIGN.md §4: results do not depend on the thread count).
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <thread>
#include <vector>

#include "pgamesh/geometry/body_moments.hpp"

namespace pgamesh {

// Faces per chunk: large enough that a chunk costs far more than starting it, small enough that
// two threads share a mesh of a few hundred thousand faces evenly.
inline constexpr std::size_t faces_per_chunk = std::size_t{1} << 14;

// The number of threads to use when the caller asks for 0 ("all"): the hardware concurrency.
inline unsigned resolve_threads(unsigned requested) {
  if (requested) return requested;
  const unsigned hw = std::thread::hardware_concurrency();
  return hw ? hw : 1;
}

// Σ over faces [0, count) of what add_range(partial, begin, end) accumulates for the faces
// [begin, end), computed on up to `threads` threads (0 = all) with the fixed chunking above.
// Partial is BoundarySums or any value-initialisable type with +=. add_range must not throw.
template <class Partial = BoundarySums, class AddRange>
Partial chunked_sums(std::size_t count, unsigned threads, const AddRange& add_range) {
  const std::size_t chunks = (count + faces_per_chunk - 1) / faces_per_chunk;
  std::vector<Partial> partial(chunks);
  std::atomic<std::size_t> next{0};
  auto work = [&] {
    for (std::size_t k; (k = next.fetch_add(1, std::memory_order_relaxed)) < chunks;) {
      const std::size_t begin = k * faces_per_chunk;
      add_range(partial[k], begin, std::min(count, begin + faces_per_chunk));
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
// faces_per_chunk faces is summed on its own from a value-initialised partial, and the partials are
// added in chunk order, so total() is chunked_sums' result bit for bit.
template <class Partial = BoundarySums>
class StreamedChunkSums {
 public:
  // The partial sums of the chunk that the next face belongs to; call next() after adding it.
  Partial& current() { return partial_; }

  // The face just added to current() is done.
  void next() {
    if (++in_chunk_ == faces_per_chunk) flush();
  }

  // The sums of every face added so far.
  Partial total() const {
    Partial t = total_;
    if (in_chunk_ > 0) t += partial_;
    return t;
  }

 private:
  void flush() {
    total_ += partial_;
    partial_ = Partial{};
    in_chunk_ = 0;
  }

  Partial total_{}, partial_{};
  std::size_t in_chunk_ = 0;
};

}  // namespace pgamesh
