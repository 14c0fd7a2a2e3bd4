// libFuzzer harness: the OFF reader with the format forced (see fuzz_common.hpp).
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return pgamesh::fuzz::read_bytes(data, size, pgamesh::MeshFormat::off);
}
