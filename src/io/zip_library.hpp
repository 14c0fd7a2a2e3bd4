// Internal: the libzip functions the 3MF container uses (zip_package.cpp), resolved from the shared
// library the first time a zip archive is read or written. Linked at start-up instead, libzip and
// the libraries it needs (OpenSSL's libcrypto among them) took about 5 ms of every run of every
// command, more than `pgamesh props` takes on a small mesh; loaded on demand they cost only the
// runs that read or write a 3MF.
#pragma once

#include <zip.h>

namespace pgamesh::detail {

// Each libzip function used, by its name without the zip_ prefix.
#define PGAMESH_ZIP_FUNCTIONS(X) \
  X(close)                       \
  X(discard)                     \
  X(error_fini)                  \
  X(error_init)                  \
  X(error_strerror)              \
  X(fclose)                      \
  X(file_add)                    \
  X(file_strerror)               \
  X(fopen_index)                 \
  X(fread)                       \
  X(get_name)                    \
  X(get_num_entries)             \
  X(name_locate)                 \
  X(open_from_source)            \
  X(set_file_compression)        \
  X(source_buffer)               \
  X(source_buffer_create)        \
  X(source_close)                \
  X(source_error)                \
  X(source_free)                 \
  X(source_keep)                 \
  X(source_open)                 \
  X(source_read)                 \
  X(source_stat)                 \
  X(stat_index)                  \
  X(stat_init)                   \
  X(strerror)

struct ZipLibrary {
#define PGAMESH_ZIP_POINTER(name) decltype(&::zip_##name) name = nullptr;
  PGAMESH_ZIP_FUNCTIONS(PGAMESH_ZIP_POINTER)
#undef PGAMESH_ZIP_POINTER
};

// The functions, loaded once (thread-safe). Throws std::runtime_error naming the library and what
// the loader said when libzip cannot be loaded (it is a run-time dependency of the io layer).
const ZipLibrary& zip_library();

}  // namespace pgamesh::detail
