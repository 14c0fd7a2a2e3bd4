// Internal: two pieces of work at once, for the passes that split their work in two (the weld of
// binary STL records, the topology pass). Each piece writes only its own data.
#pragma once

#include <exception>
#include <thread>

namespace pgamesh::detail {

// Runs `first` on the calling thread and `second` on a thread of its own, or both on the calling
// thread, first then second, when `parallel` is false. Rethrows an exception of either.
template <class First, class Second>
void run_both(bool parallel, First&& first, Second&& second) {
  if (!parallel) {
    first();
    second();
    return;
  }
  std::exception_ptr second_error;
  std::thread thread([&] {
    try {
      second();
    } catch (...) {
      second_error = std::current_exception();
    }
  });
  try {
    first();
  } catch (...) {
    thread.join();
    throw;
  }
  thread.join();
  if (second_error) std::rethrow_exception(second_error);
}

}  // namespace pgamesh::detail
