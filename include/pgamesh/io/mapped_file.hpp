// A whole input file as one read-only byte span: memory-mapped for regular files (the readers then
// stream through the page cache without copying), read into a buffer for pipes and stdin.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

namespace pgamesh {

class MappedFile {
 public:
  // Maps `path` read-only. "-" reads standard input; pipes and other non-regular files are read
  // into memory. Throws InputError for a missing or unreadable path and for a directory. An empty
  // file maps to an empty span.
  static MappedFile open(const std::string& path);

  MappedFile() = default;
  MappedFile(MappedFile&& other) noexcept;
  MappedFile& operator=(MappedFile&& other) noexcept;
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;
  ~MappedFile();

  // The file's bytes, valid while this object lives.
  std::span<const char> bytes() const { return {data_, size_}; }
  // The path given to open().
  const std::string& path() const { return path_; }
  // Whether bytes() is a read-only file mapping (whose pages may be released with madvise
  // MADV_DONTNEED and are read back from the file when touched again), not a buffer of our own.
  bool mapped() const { return mapped_; }
  // The open read-only descriptor of a mapped file (closed with this object), or −1: for reading
  // parts of the file with pread instead of touching the mapping's pages (BinaryStlView::file).
  int descriptor() const { return descriptor_; }

 private:
  void release() noexcept;

  std::string path_;
  const char* data_ = nullptr;
  std::size_t size_ = 0;
  bool mapped_ = false;      // data_ is an mmap region to munmap
  int descriptor_ = -1;      // the mapped file, open
  std::vector<char> owned_;  // contents of a pipe or stdin
};

}  // namespace pgamesh
