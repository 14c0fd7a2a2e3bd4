#include "bounded_body.hpp"

#include <chrono>

namespace pgamesh::viewer {

namespace {

// Past the limit, the rest of the body is read and dropped for a while before the 413: a socket
// closed with unread data is reset, and a client reset while still sending loses the answer it
// was sent. Bounded in bytes (kBodyDrainBytes) and time, so a body without end is cut all the same.
constexpr std::chrono::seconds kDrainTime{1};

}  // namespace

BodyRead read_bounded_body(const httplib::ContentReader& reader, std::size_t limit,
                           std::string& out) {
  out.clear();
  bool over_limit = false;
  std::size_t dropped = 0;
  std::chrono::steady_clock::time_point drain_end;
  const bool read = reader([&](const char* data, std::size_t size) {
    if (!over_limit && size <= limit - out.size()) {
      out.append(data, size);
      return true;
    }
    if (!over_limit) {
      over_limit = true;
      out.clear();
      out.shrink_to_fit();
      drain_end = std::chrono::steady_clock::now() + kDrainTime;
    }
    dropped += size;
    return dropped <= kBodyDrainBytes && std::chrono::steady_clock::now() < drain_end;
  });
  if (over_limit) return BodyRead::too_large;
  return read ? BodyRead::complete : BodyRead::unreadable;
}

}  // namespace pgamesh::viewer
