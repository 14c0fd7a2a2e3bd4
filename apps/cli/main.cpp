// pgamesh — the command-line tool. `pgamesh <command> FILE [options]` (DESIGN.md §5).
#include <cstdio>
#include <cstring>
#include <string>
#ifdef __GLIBC__
#include <malloc.h>
#endif

#include "commands.hpp"

namespace {

void print_usage(std::FILE* out) {
  std::fprintf(out,
               "usage: pgamesh <command> [FILE] [options]\n"
               "\n"
               "commands:\n");
  for (const auto& c : pgamesh::cli::commands())
    std::fprintf(out, "  %-8s %s\n", c.name, c.summary);
  std::fprintf(out,
               "\n"
               "  pgamesh <command> --help   options of one command\n"
               "  pgamesh --version          print the version\n");
}

}  // namespace

int main(int argc, char** argv) {
#ifdef __GLIBC__
  // Arrays above 128 KiB get mappings of their own, unmapped when freed. glibc otherwise raises
  // this threshold to the size of the largest mapped block freed so far (a reader's arrays), so
  // the weld's and the edge pass's arrays of a few MB then come from the heap, where a freed one
  // below a live one stays resident: measured on a 10^6-triangle PLY, 2 MB more at the peak of
  // props (docs/benchmarks.md).
  mallopt(M_MMAP_THRESHOLD, 128 * 1024);
#endif
  if (argc < 2) {
    print_usage(stderr);
    return 2;
  }
  const std::string first = argv[1];
  if (first == "--version" || first == "version") {
    std::printf("pgamesh %s\n", PGAMESH_VERSION);
    return 0;
  }
  if (first == "--help" || first == "-h" || first == "help") {
    print_usage(stdout);
    return 0;
  }
  for (const auto& c : pgamesh::cli::commands())
    if (first == c.name) return c.run(argc - 1, argv + 1);
  std::fprintf(stderr, "pgamesh: unknown command '%s'\n\n", first.c_str());
  print_usage(stderr);
  return 2;
}
