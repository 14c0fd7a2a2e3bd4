#include "io/stl_record_blocks.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <vector>

#include "io/text_cursor.hpp"
#include "pgamesh/core/input_error.hpp"

namespace pgamesh::detail {

const unsigned char* record_block(const BinaryStlView& view, std::uint64_t first,
                                  std::uint64_t count, const std::string& name) {
  const std::uint64_t stride = view.layout.stride;
  if (view.file < 0) return view.records + stride * first;
  thread_local std::vector<unsigned char> buffer(records_per_block * stl_record_bytes);
  const std::uint64_t offset = view.first_record_offset + stride * first;
  const std::size_t bytes = stride * count;
  if (buffer.size() < bytes) buffer.resize(bytes);
  std::size_t done = 0;
  while (done < bytes) {
    const ssize_t n =
        ::pread(view.file, buffer.data() + done, bytes - done, static_cast<off_t>(offset + done));
    if (n > 0) {
      done += static_cast<std::size_t>(n);
    } else if (n == 0) {
      throw InputError(name, byte_position(offset + done),
                       "the file ends here, before the triangles its header declares (it was "
                       "shortened while being read)");
    } else if (errno != EINTR) {
      throw InputError(name, byte_position(offset + done),
                       std::string("cannot read: ") + std::strerror(errno));
    }
  }
  return buffer.data();
}

}  // namespace pgamesh::detail
