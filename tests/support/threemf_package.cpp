#include "support/threemf_package.hpp"

#include <zip.h>

#include <cstring>
#include <stdexcept>

namespace pgamesh::test {

std::string zip_bytes(const std::vector<ZipEntry>& entries) {
  zip_error_t error;
  zip_error_init(&error);
  zip_source_t* buffer = zip_source_buffer_create(nullptr, 0, 0, &error);
  zip_source_keep(buffer);
  zip_t* zip = zip_open_from_source(buffer, ZIP_TRUNCATE, &error);
  if (!zip) throw std::runtime_error("zip_open_from_source failed");
  for (const ZipEntry& e : entries) {
    zip_source_t* s = zip_source_buffer(zip, e.data.data(), e.data.size(), 0);
    const zip_int64_t i = zip_file_add(zip, e.name.c_str(), s, ZIP_FL_ENC_RAW);
    if (i < 0) throw std::runtime_error("zip_file_add failed: " + e.name);
    zip_set_file_compression(zip, static_cast<zip_uint64_t>(i),
                             e.deflate ? ZIP_CM_DEFLATE : ZIP_CM_STORE, 0);
  }
  if (zip_close(zip) != 0) throw std::runtime_error("zip_close failed");
  zip_stat_t st;
  zip_stat_init(&st);
  zip_source_stat(buffer, &st);
  std::string out(st.size, '\0');
  zip_source_open(buffer);
  zip_source_read(buffer, out.data(), out.size());
  zip_source_close(buffer);
  zip_source_free(buffer);
  return out;
}

std::string threemf_box(int id, double a, double b, double c, const std::string& name) {
  const double v[8][3] = {{0, 0, 0}, {a, 0, 0}, {a, b, 0}, {0, b, 0},
                          {0, 0, c}, {a, 0, c}, {a, b, c}, {0, b, c}};
  const int t[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                        {3, 7, 6}, {3, 6, 2}, {0, 4, 7}, {0, 7, 3}, {1, 2, 6}, {1, 6, 5}};
  std::string s = "<object id=\"" + std::to_string(id) + "\" type=\"model\"";
  if (!name.empty()) s += " name=\"" + name + "\"";
  s += ">\n<mesh>\n<vertices>\n";
  for (const auto& p : v)
    s += "<vertex x=\"" + std::to_string(p[0]) + "\" y=\"" + std::to_string(p[1]) + "\" z=\"" +
         std::to_string(p[2]) + "\"/>\n";
  s += "</vertices>\n<triangles>\n";
  for (const auto& f : t)
    s += "<triangle v1=\"" + std::to_string(f[0]) + "\" v2=\"" + std::to_string(f[1]) + "\" v3=\"" +
         std::to_string(f[2]) + "\"/>\n";
  return s + "</triangles>\n</mesh>\n</object>\n";
}

std::string threemf_model(const std::string& resources, const std::string& build,
                          const std::string& unit_attribute) {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<model " + unit_attribute +
         " xmlns=\"http://schemas.microsoft.com/3dmanufacturing/core/2015/02\">\n<resources>\n" +
         resources + "</resources>\n<build>\n" + build + "</build>\n</model>\n";
}

std::string threemf_package(const std::string& model) {
  const std::string types =
      R"(<?xml version="1.0" encoding="UTF-8"?>
<Types xmlns="http://schemas.openxmlformats.org/package/2006/content-types">
<Default Extension="rels" ContentType="application/vnd.openxmlformats-package.relationships+xml"/>
<Default Extension="model" ContentType="application/vnd.ms-package.3dmanufacturing-3dmodel+xml"/>
</Types>)";
  const std::string rels =
      R"(<?xml version="1.0" encoding="UTF-8"?>
<Relationships xmlns="http://schemas.openxmlformats.org/package/2006/relationships">
<Relationship Target="/3D/3dmodel.model" Id="rel0" Type="http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel"/>
</Relationships>)";
  return zip_bytes(
      {{"[Content_Types].xml", types}, {"_rels/.rels", rels}, {"3D/3dmodel.model", model}});
}

namespace {

void put16(std::string& z, std::size_t at, std::uint16_t v) {
  z[at] = static_cast<char>(v & 0xFF);
  z[at + 1] = static_cast<char>(v >> 8);
}
void put32(std::string& z, std::size_t at, std::uint32_t v) {
  for (int k = 0; k < 4; ++k) z[at + k] = static_cast<char>((v >> (8 * k)) & 0xFF);
}
std::uint16_t get16(const std::string& z, std::size_t at) {
  return static_cast<std::uint16_t>(static_cast<unsigned char>(z[at]) |
                                    static_cast<unsigned char>(z[at + 1]) << 8);
}

// Calls edit(header offset, field offset table) for the local header (signature PK\3\4, name at
// +30) and the central directory header (PK\1\2, name at +46) of `name`. The fields: flags,
// method, uncompressed size at (+6, +8, +22) locally and (+8, +10, +24) centrally.
template <class Edit>
bool edit_entry(std::string& z, const std::string& name, Edit edit) {
  bool found = false;
  for (std::size_t at = 0; at + 46 <= z.size(); ++at) {
    const bool local = std::memcmp(&z[at], "PK\x03\x04", 4) == 0;
    const bool central = std::memcmp(&z[at], "PK\x01\x02", 4) == 0;
    if (!local && !central) continue;
    const std::size_t name_at = at + (local ? 30 : 46);
    const std::uint16_t len = get16(z, at + (local ? 26 : 28));
    if (len != name.size() || z.compare(name_at, len, name) != 0) continue;
    if (local)
      edit(at + 6, at + 8, at + 22);
    else
      edit(at + 8, at + 10, at + 24);
    found = true;
  }
  return found;
}

}  // namespace

bool set_zip_flags(std::string& zip, const std::string& name, std::uint16_t bits) {
  return edit_entry(zip, name, [&](std::size_t flags, std::size_t, std::size_t) {
    put16(zip, flags, static_cast<std::uint16_t>(get16(zip, flags) | bits));
  });
}

bool set_zip_method(std::string& zip, const std::string& name, std::uint16_t method) {
  return edit_entry(zip, name,
                    [&](std::size_t, std::size_t m, std::size_t) { put16(zip, m, method); });
}

bool set_zip_size(std::string& zip, const std::string& name, std::uint32_t uncompressed) {
  return edit_entry(zip, name,
                    [&](std::size_t, std::size_t, std::size_t s) { put32(zip, s, uncompressed); });
}

}  // namespace pgamesh::test
