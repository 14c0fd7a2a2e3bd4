// A request body read through httplib's content reader, counted as it arrives. httplib's own
// payload limit holds only for bodies with a Content-Length: a chunked body (or one ending at the
// connection's close) is read whole, and form-urlencoded bodies are refused beyond 8 KiB whatever
// the limit. Read here, every body is raw bytes bounded by the same limit.
#pragma once

#include <httplib.h>

#include <cstddef>
#include <string>

namespace pgamesh::viewer {

/// How much of a body past the limit is read and dropped so that the client reads the 413.
constexpr std::size_t kBodyDrainBytes = std::size_t{64} << 20;

enum class BodyRead {
  complete,    // `out` holds the whole body
  too_large,   // over the limit: `out` is empty, the rest of the body possibly unread
  unreadable,  // malformed chunks, cut short, or an unsupported Content-Encoding
};

/// Reads the body into `out`, keeping nothing more once it exceeds `limit` bytes (counted after
/// decoding any Content-Encoding, so a compressed body cannot expand past the limit). Past the
/// limit the rest is read and dropped, at most 64 MiB or 1 s more, so that the client reads the
/// 413; a longer body is cut there.
BodyRead read_bounded_body(const httplib::ContentReader& reader, std::size_t limit,
                           std::string& out);

}  // namespace pgamesh::viewer
