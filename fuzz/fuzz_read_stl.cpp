// libFuzzer harness: the STL readers (forced STL: ASCII or binary by size) and the binary view.
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return pgamesh::fuzz::read_bytes(data, size, pgamesh::MeshFormat::stl_binary);
}
