// libFuzzer harness: the glTF 2.0 reader (JSON .gltf with data: URIs, and GLB) with the format
// forced (see fuzz_common.hpp). Bytes in memory have no folder: external buffers are refused.
#include "fuzz_common.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return pgamesh::fuzz::read_bytes(data, size, pgamesh::MeshFormat::gltf);
}
