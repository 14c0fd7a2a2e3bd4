#include "pgamesh/io/write_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

namespace pgamesh {

namespace {

[[noreturn]] void fail(const std::string& path, const char* what, int error) {
  throw std::runtime_error(path + ": " + what + ": " + std::strerror(error));
}

// A temporary file next to `path`, created exclusively (O_EXCL: never someone else's file) with
// mode 0666 so that the umask applies as it would to `path` itself. Returns its descriptor.
int create_temporary(const std::string& path, std::string& temporary) {
  static std::atomic<unsigned> counter{0};
  for (int attempt = 0; attempt < 100; ++attempt) {
    temporary = path + ".tmp-" + std::to_string(getpid()) + "-" + std::to_string(counter++);
    const int fd = open(temporary.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
    if (fd >= 0) return fd;
    if (errno != EEXIST) fail(path, "cannot write", errno);
  }
  fail(path, "cannot create a temporary file", EEXIST);
}

}  // namespace

void write_file_atomically(const std::string& path, std::string_view bytes) {
  std::string temporary;
  const int fd = create_temporary(path, temporary);
  const char* data = bytes.data();
  std::size_t left = bytes.size();
  int error = 0;
  while (left > 0 && !error) {
    const ssize_t n = write(fd, data, left);
    if (n < 0 && errno != EINTR) error = errno;
    if (n > 0) {
      data += n;
      left -= static_cast<std::size_t>(n);
    }
  }
  // On disk before the rename: otherwise a crash right after it could leave an empty file.
  if (!error && fsync(fd) != 0) error = errno;
  if (close(fd) != 0 && !error) error = errno;
  if (!error && std::rename(temporary.c_str(), path.c_str()) != 0) error = errno;
  if (error) {
    unlink(temporary.c_str());
    fail(path, "write failed", error);
  }
}

}  // namespace pgamesh
