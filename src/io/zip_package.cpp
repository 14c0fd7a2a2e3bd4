#include "io/zip_package.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>

#include "io/text_cursor.hpp"
#include "io/zip_library.hpp"
#include "pgamesh/core/input_error.hpp"

namespace pgamesh::detail {

namespace {

std::string without_slash(std::string_view part) {
  if (!part.empty() && part.front() == '/') part.remove_prefix(1);
  return std::string(part);
}

// A name that stays inside the package: relative, no "." or ".." segment, no backslash (a
// Windows separator some unzip tools honour) and no control bytes.
bool safe_entry_name(std::string_view n) {
  if (n.empty() || n.front() == '/') return false;
  for (char c : n)
    if (c == '\\' || static_cast<unsigned char>(c) < 0x20) return false;
  std::size_t start = 0;
  while (start <= n.size()) {
    const std::size_t end = std::min(n.find('/', start), n.size());
    const std::string_view segment = n.substr(start, end - start);
    if (segment == ".." || segment == ".") return false;
    start = end + 1;
  }
  return true;
}

std::string quoted(std::string_view s) {
  std::string out = "'";
  for (char c : s) out += static_cast<unsigned char>(c) < 0x20 ? '?' : c;
  return out + "'";
}

}  // namespace

std::uint64_t ZipBudget::for_archive(std::uint64_t archive_bytes) const {
  const std::uint64_t max = std::numeric_limits<std::uint64_t>::max();
  const std::uint64_t scaled = archive_bytes > max / ratio ? max : archive_bytes * ratio;
  return std::min(cap, scaled > max - allowance ? max : scaled + allowance);
}

struct ZipPackage::Archive {
  zip_t* zip = nullptr;
  ~Archive() {
    if (zip) zip_library().discard(zip);
  }
};

ZipPackage::ZipPackage(std::span<const char> bytes, const std::string& name, ZipBudget budget)
    : archive_(std::make_unique<Archive>()),
      name_(name),
      budget_(budget.for_archive(bytes.size())) {
  const ZipLibrary& lib = zip_library();
  zip_error_t error;
  lib.error_init(&error);
  zip_source_t* source = lib.source_buffer_create(bytes.data(), bytes.size(), 0, &error);
  if (source) {
    archive_->zip = lib.open_from_source(source, ZIP_RDONLY | ZIP_CHECKCONS, &error);
    if (!archive_->zip) lib.source_free(source);
  }
  if (!archive_->zip) {
    const std::string why = lib.error_strerror(&error);
    lib.error_fini(&error);
    throw InputError(
        name, byte_position(0),
        "not a readable zip archive (3MF is a zip package; truncated or damaged?): " + why);
  }
  lib.error_fini(&error);
  const zip_int64_t entries = lib.get_num_entries(archive_->zip, 0);
  for (zip_int64_t i = 0; i < entries; ++i) {
    const char* entry = lib.get_name(archive_->zip, static_cast<zip_uint64_t>(i), ZIP_FL_ENC_RAW);
    if (!entry)
      throw InputError(name, byte_position(0),
                       "zip archive: entry " + std::to_string(i) + " has no readable name");
    if (!safe_entry_name(entry))
      throw InputError(name, byte_position(0),
                       "zip archive: entry name " + quoted(entry) +
                           " leaves the package (path traversal: absolute, '..', '.' or '\\')");
  }
}

ZipPackage::~ZipPackage() = default;

bool ZipPackage::has(std::string_view part) const {
  const ZipLibrary& lib = zip_library();
  return lib.name_locate(archive_->zip, without_slash(part).c_str(), ZIP_FL_NOCASE) >= 0;
}

PartBytes ZipPackage::read(std::string_view part) const {
  const ZipLibrary& lib = zip_library();
  const std::string entry = without_slash(part);
  const std::string what = "zip entry " + quoted(entry) + ": ";
  const zip_int64_t index = lib.name_locate(archive_->zip, entry.c_str(), ZIP_FL_NOCASE);
  if (index < 0) throw InputError(name_, byte_position(0), what + "missing from the package");
  zip_stat_t st;
  lib.stat_init(&st);
  if (lib.stat_index(archive_->zip, static_cast<zip_uint64_t>(index), 0, &st) != 0)
    throw InputError(name_, byte_position(0), what + lib.strerror(archive_->zip));
  if ((st.valid & ZIP_STAT_ENCRYPTION_METHOD) && st.encryption_method != ZIP_EM_NONE)
    throw InputError(name_, byte_position(0), what + "encrypted (not supported)");
  if (!(st.valid & ZIP_STAT_COMP_METHOD) ||
      (st.comp_method != ZIP_CM_STORE && st.comp_method != ZIP_CM_DEFLATE))
    throw InputError(name_, byte_position(0),
                     what + "compression method " + std::to_string(st.comp_method) +
                         " not supported (stored and deflate only)");
  const std::uint64_t declared = st.size;
  if (declared > budget_)
    throw InputError(name_, byte_position(0),
                     what + "declares " + std::to_string(declared) +
                         " bytes uncompressed, beyond the limit of " + std::to_string(budget_) +
                         " bytes for this archive (zip bomb?)");
  zip_file_t* file = lib.fopen_index(archive_->zip, static_cast<zip_uint64_t>(index), 0);
  if (!file) throw InputError(name_, byte_position(0), what + lib.strerror(archive_->zip));
  struct Closer {
    zip_file_t* f;
    ~Closer() { zip_library().fclose(f); }
  } closer{file};
  // Inflated in steps into a buffer of the declared size; one byte more than declared is an
  // error at once, so a lying header cannot make us inflate beyond it (and the declared size is
  // already within the budget).
  PartBytes out{uninitialized_array<char>(declared ? declared : 1),
                static_cast<std::size_t>(declared)};
  std::uint64_t got = 0;
  char probe = 0;
  for (;;) {
    const std::uint64_t room = declared - got;
    char* dst = room ? out.begin() + got : &probe;
    const zip_uint64_t step = room ? std::min<std::uint64_t>(room, std::uint64_t{1} << 22) : 1;
    const zip_int64_t n = lib.fread(file, dst, step);
    if (n < 0)
      throw InputError(name_, byte_position(0),
                       what + "cannot be inflated: " + lib.file_strerror(file) +
                           " (truncated or damaged archive?)");
    if (n == 0) break;
    if (!room)
      throw InputError(name_, byte_position(0),
                       what + "inflates beyond its declared size of " + std::to_string(declared) +
                           " bytes (damaged or hostile archive)");
    got += static_cast<std::uint64_t>(n);
  }
  if (got != declared)
    throw InputError(name_, byte_position(0),
                     what + "inflates to " + std::to_string(got) + " bytes, not the declared " +
                         std::to_string(declared) + " (truncated archive?)");
  return out;
}

std::string zip_archive(const std::vector<std::pair<std::string, std::string>>& entries) {
  const ZipLibrary& lib = zip_library();
  auto failed = [](const char* what, const char* why) {
    return std::runtime_error(std::string("zip archive: ") + what + ": " + why);
  };
  zip_error_t error;
  lib.error_init(&error);
  zip_source_t* buffer = lib.source_buffer_create(nullptr, 0, 0, &error);
  if (!buffer) throw failed("buffer", lib.error_strerror(&error));
  lib.source_keep(buffer);  // read back after zip_close
  struct Release {
    zip_source_t* s;
    ~Release() { zip_library().source_free(s); }
  } release{buffer};
  zip_t* zip = lib.open_from_source(buffer, ZIP_TRUNCATE, &error);
  if (!zip) {
    lib.source_free(buffer);  // the reference the archive did not take
    throw failed("open", lib.error_strerror(&error));
  }
  for (const auto& [entry, data] : entries) {
    zip_source_t* s = lib.source_buffer(zip, data.data(), data.size(), 0);
    const zip_int64_t index = s ? lib.file_add(zip, entry.c_str(), s, ZIP_FL_ENC_UTF_8) : -1;
    if (index < 0) {
      if (s) lib.source_free(s);
      const std::string why = lib.strerror(zip);
      lib.discard(zip);
      throw failed(entry.c_str(), why.c_str());
    }
    lib.set_file_compression(zip, static_cast<zip_uint64_t>(index), ZIP_CM_DEFLATE, 0);
  }
  if (lib.close(zip) != 0) {
    const std::string why = lib.strerror(zip);
    lib.discard(zip);
    throw failed("close", why.c_str());
  }
  zip_stat_t st;
  lib.stat_init(&st);
  if (lib.source_stat(buffer, &st) != 0 || lib.source_open(buffer) != 0)
    throw failed("read back", lib.error_strerror(lib.source_error(buffer)));
  std::string out(static_cast<std::size_t>(st.size), '\0');
  const zip_int64_t n = lib.source_read(buffer, out.data(), out.size());
  lib.source_close(buffer);
  if (n < 0 || static_cast<std::uint64_t>(n) != st.size) throw failed("read back", "short read");
  return out;
}

}  // namespace pgamesh::detail
