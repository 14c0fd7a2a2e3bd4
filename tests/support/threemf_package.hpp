// 3MF packages built in memory for the tests, with libzip directly (independently of the library's
// writer): model XML from pieces, the zip archive, and the byte surgery that makes hostile ones (a
// header that lies about the size, an encryption flag, an unknown compression method).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pgamesh::test {

struct ZipEntry {
  std::string name;
  std::string data;
  bool deflate = true;  // false: stored
};

// The archive of `entries`, in order.
std::string zip_bytes(const std::vector<ZipEntry>& entries);

// An axis-aligned box [0,a]×[0,b]×[0,c] as a 3MF <object> (8 vertices, 12 outward triangles; one
// element a line, the vertices on lines 3–10 of the object's text, the triangles on 13–24).
std::string threemf_box(int id, double a, double b, double c, const std::string& name = "");

// A 3MF model part: <model> with `unit_attribute` (e.g. unit="inch", or nothing), <resources>
// and <build>; one element a line (the declaration is line 1, <model> 2, <resources> 3).
std::string threemf_model(const std::string& resources, const std::string& build,
                          const std::string& unit_attribute = "");

// A 3MF package: [Content_Types].xml, _rels/.rels naming /3D/3dmodel.model as the model part, and
// `model` as 3D/3dmodel.model.
std::string threemf_package(const std::string& model);

// Field surgery on the entry named `name`, in its local header and in the central directory: the
// general-purpose flags (bits or'ed in), the compression method, the uncompressed size. Returns
// false when the entry is not found.
bool set_zip_flags(std::string& zip, const std::string& name, std::uint16_t bits);
bool set_zip_method(std::string& zip, const std::string& name, std::uint16_t method);
bool set_zip_size(std::string& zip, const std::string& name, std::uint32_t uncompressed);

}  // namespace pgamesh::test
