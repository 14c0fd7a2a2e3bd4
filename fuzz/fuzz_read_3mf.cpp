// libFuzzer harness: the 3MF reader (zip package, relationships, model XML) with the format forced
// (see fuzz_common.hpp). The seeds in corpus/3mf are tiny packages; the fuzzer mutates the zip
// bytes, so most inputs exercise the archive guards (docs/formats.md, "3MF").
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return pgamesh::fuzz::read_bytes(data, size, pgamesh::MeshFormat::threemf);
}
