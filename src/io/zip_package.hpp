// Internal: the zip container of an OPC package (3MF), read from bytes in memory with libzip and
// guarded against hostile archives (docs/formats.md, "3MF"): every entry name is checked for path
// traversal when the archive is opened; a part is inflated only if it is stored or deflated and not
// encrypted, with a byte budget checked while inflating (not only the declared size), so that a zip
// bomb costs at most the budget in memory and time.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "detail/memory/uninitialized_array.hpp"

namespace pgamesh::detail {

// The inflated bytes of a part, on huge pages when large (written in full, never zeroed first).
struct PartBytes {
  UninitializedArray<char> data;
  std::size_t size = 0;
  char* begin() const { return data.get(); }
  char* end() const { return data.get() + size; }
};

// The most bytes one part may inflate to: `ratio` times the archive's size plus `allowance`, and
// never more than `cap`. Deflate's own limit is about 1032:1; real model XML compresses 3–20×.
struct ZipBudget {
  std::uint64_t ratio = 256;
  std::uint64_t allowance = std::uint64_t{32} << 20;  // 32 MiB
  std::uint64_t cap = std::uint64_t{4} << 30;         // 4 GiB
  std::uint64_t for_archive(std::uint64_t archive_bytes) const;
};

class ZipPackage {
 public:
  // Opens the archive in `bytes` (which must outlive the package); `name` is the file named in
  // errors. Throws InputError for an unreadable or truncated archive and for an entry whose name
  // leaves the package ("../", an absolute path, a backslash or a NUL).
  ZipPackage(std::span<const char> bytes, const std::string& name, ZipBudget budget = {});
  ~ZipPackage();
  ZipPackage(const ZipPackage&) = delete;
  ZipPackage& operator=(const ZipPackage&) = delete;

  // Whether the package holds the part (an OPC part name, with or without the leading '/',
  // matched ignoring ASCII letter case as OPC requires).
  bool has(std::string_view part) const;

  // The inflated bytes of the part. Throws InputError for a missing part, an encrypted entry, a
  // compression method other than stored or deflate, a declared or actual size beyond the budget,
  // an actual size other than the declared one, and a CRC or inflate error.
  PartBytes read(std::string_view part) const;

  std::uint64_t budget() const { return budget_; }

 private:
  struct Archive;
  std::unique_ptr<Archive> archive_;
  std::string name_;
  std::uint64_t budget_ = 0;
};

// A zip archive of the given entries (name, bytes), each deflated, in the given order: the
// container of the 3MF writer.
std::string zip_archive(const std::vector<std::pair<std::string, std::string>>& entries);

}  // namespace pgamesh::detail
