#include "pgamesh/io/mapped_file.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

#include "pgamesh/core/input_error.hpp"

namespace pgamesh {

namespace {

[[noreturn]] void fail_open(const std::string& path, const std::string& problem) {
  throw InputError(path, InputPosition{}, problem);
}

// Reads a stream that cannot be mapped (pipe, terminal, stdin) to its end.
std::vector<char> read_all(int fd, const std::string& path) {
  std::vector<char> out;
  std::size_t used = 0;
  out.resize(1 << 16);
  for (;;) {
    if (used == out.size()) out.resize(out.size() * 2);
    const ssize_t n = ::read(fd, out.data() + used, out.size() - used);
    if (n == 0) break;
    if (n < 0) {
      if (errno == EINTR) continue;
      fail_open(path, std::string("cannot read: ") + std::strerror(errno));
    }
    used += static_cast<std::size_t>(n);
  }
  out.resize(used);
  return out;
}

}  // namespace

MappedFile MappedFile::open(const std::string& path) {
  MappedFile f;
  f.path_ = path;
  if (path == "-") {
    f.owned_ = read_all(STDIN_FILENO, path);
    f.data_ = f.owned_.data();
    f.size_ = f.owned_.size();
    return f;
  }
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) fail_open(path, std::string("cannot open: ") + std::strerror(errno));
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    const int e = errno;
    ::close(fd);
    fail_open(path, std::string("cannot stat: ") + std::strerror(e));
  }
  if (S_ISDIR(st.st_mode)) {
    ::close(fd);
    fail_open(path, "is a directory, not a mesh file");
  }
  if (!S_ISREG(st.st_mode)) {
    try {
      f.owned_ = read_all(fd, path);
    } catch (...) {
      ::close(fd);
      throw;
    }
    ::close(fd);
    f.data_ = f.owned_.data();
    f.size_ = f.owned_.size();
    return f;
  }
  const auto size = static_cast<std::size_t>(st.st_size);
  if (size == 0) {
    ::close(fd);
    return f;
  }
  void* p = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE, fd, 0);
  const int e = errno;
  if (p == MAP_FAILED) {
    ::close(fd);
    fail_open(path, std::string("cannot map: ") + std::strerror(e));
  }
  ::madvise(p, size, MADV_SEQUENTIAL);
  f.data_ = static_cast<const char*>(p);
  f.size_ = size;
  f.mapped_ = true;
  f.descriptor_ = fd;  // kept open for pread (descriptor())
  return f;
}

MappedFile::MappedFile(MappedFile&& other) noexcept {
  *this = std::move(other);
}

MappedFile& MappedFile::operator=(MappedFile&& other) noexcept {
  if (this == &other) return *this;
  release();
  path_ = std::move(other.path_);
  owned_ = std::move(other.owned_);
  mapped_ = std::exchange(other.mapped_, false);
  descriptor_ = std::exchange(other.descriptor_, -1);
  size_ = std::exchange(other.size_, 0);
  const char* d = std::exchange(other.data_, nullptr);
  data_ = mapped_ ? d : owned_.data();
  return *this;
}

MappedFile::~MappedFile() {
  release();
}

void MappedFile::release() noexcept {
  if (mapped_ && data_) ::munmap(const_cast<char*>(data_), size_);
  if (descriptor_ >= 0) ::close(descriptor_);
  descriptor_ = -1;
  data_ = nullptr;
  size_ = 0;
  mapped_ = false;
  owned_.clear();
}

}  // namespace pgamesh
