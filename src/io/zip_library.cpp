#include "io/zip_library.hpp"

#include <dlfcn.h>

#include <stdexcept>
#include <string>

// The file name the loader finds libzip by (its SONAME, e.g. libzip.so.4), set by CMakeLists.txt
// from the library the build found.
#ifndef PGAMESH_LIBZIP_SONAME
#error "PGAMESH_LIBZIP_SONAME must name the libzip shared library"
#endif

namespace pgamesh::detail {

namespace {

ZipLibrary load_zip_library() {
  const char* file = PGAMESH_LIBZIP_SONAME;
  void* handle = dlopen(file, RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = dlerror();
    throw std::runtime_error(std::string("cannot load libzip (") + file + "), which reading and " +
                             "writing 3MF need: " + (why ? why : "unknown error"));
  }
  // Never closed: the functions are used for the rest of the process.
  ZipLibrary z;
#define PGAMESH_ZIP_RESOLVE(name)                                           \
  z.name = reinterpret_cast<decltype(z.name)>(dlsym(handle, "zip_" #name)); \
  if (!z.name) throw std::runtime_error(std::string(file) + " has no function zip_" #name);
  PGAMESH_ZIP_FUNCTIONS(PGAMESH_ZIP_RESOLVE)
#undef PGAMESH_ZIP_RESOLVE
  return z;
}

}  // namespace

const ZipLibrary& zip_library() {
  static const ZipLibrary z = load_zip_library();
  return z;
}

}  // namespace pgamesh::detail
