// glTF 2.0 (Khronos): a JSON document (.gltf, its buffers in data: URIs or in files beside it) or
// the same in a binary container (.glb: a 12-byte header, a JSON chunk and a BIN chunk). The
// triangle primitives (modes 4, 5, 6) of every mesh instanced by the nodes of the default scene
// (all root nodes without one) are placed by the node transforms, composed in double, and appended
// as one MeshPart per node. Units are metres by the specification. docs/formats.md, "glTF 2.0".
//
// Every count, offset and stride is checked against the bytes that hold it before anything is
// allocated or read; errors name the file and the JSON path ("accessors[3].count") or the byte.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "detail/memory/huge_pages.hpp"
#include "io/affine.hpp"
#include "io/readers.hpp"
#include "io/text_cursor.hpp"
#include "pgamesh/core/input_error.hpp"
#include "pgamesh/io/mapped_file.hpp"

namespace pgamesh::detail {

namespace {

using Json = nlohmann::json;

constexpr std::uint32_t glb_magic = 0x46546C67;       // "glTF"
constexpr std::uint32_t glb_json_chunk = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t glb_bin_chunk = 0x004E4942;   // "BIN\0"

std::uint32_t le32(const char* p) {
  std::uint32_t v;
  std::memcpy(&v, p, 4);
  if constexpr (std::endian::native == std::endian::big) v = __builtin_bswap32(v);
  return v;
}

std::size_t component_bytes(int type) {
  switch (type) {
    case 5120:
    case 5121:
      return 1;
    case 5122:
    case 5123:
      return 2;
    case 5125:
    case 5126:
      return 4;
    default:
      return 0;
  }
}

std::size_t type_components(const std::string& type) {
  if (type == "SCALAR") return 1;
  if (type == "VEC2") return 2;
  if (type == "VEC3") return 3;
  if (type == "VEC4" || type == "MAT2") return 4;
  if (type == "MAT3") return 9;
  if (type == "MAT4") return 16;
  return 0;
}

// One component at p, as a double: integers as they are, or mapped to [0, 1] / [−1, 1] when
// normalized (glTF 2.0 §3.11, "Animations": c / (2^n − 1), max(c / (2^(n−1) − 1), −1)).
double component(const char* p, int type, bool normalized) {
  switch (type) {
    case 5120: {
      const auto v = static_cast<std::int8_t>(*p);
      return normalized ? std::max(v / 127.0, -1.0) : v;
    }
    case 5121: {
      const auto v = static_cast<std::uint8_t>(*p);
      return normalized ? v / 255.0 : v;
    }
    case 5122: {
      std::uint16_t u;
      std::memcpy(&u, p, 2);
      if constexpr (std::endian::native == std::endian::big) u = __builtin_bswap16(u);
      const auto v = static_cast<std::int16_t>(u);
      return normalized ? std::max(v / 32767.0, -1.0) : v;
    }
    case 5123: {
      std::uint16_t u;
      std::memcpy(&u, p, 2);
      if constexpr (std::endian::native == std::endian::big) u = __builtin_bswap16(u);
      return normalized ? u / 65535.0 : u;
    }
    case 5125: {
      const std::uint32_t u = le32(p);
      return normalized ? u / 4294967295.0 : u;
    }
    default: {
      float f;
      std::memcpy(&f, p, 4);
      if constexpr (std::endian::native == std::endian::big)
        f = std::bit_cast<float>(__builtin_bswap32(std::bit_cast<std::uint32_t>(f)));
      return f;
    }
  }
}

// An accessor resolved to bytes: element i is at data + i × stride (data null: all zeros), plus
// its sparse substitutions.
struct AccessorView {
  std::string path;  // "accessors[3]"
  const char* data = nullptr;
  std::size_t stride = 0;
  int component_type = 0;
  std::size_t components = 0;
  std::uint64_t count = 0;
  bool normalized = false;
  std::vector<std::uint64_t> sparse_indices;  // ascending
  const char* sparse_values = nullptr;        // tightly packed, one element per sparse index

  double get(std::uint64_t i, std::size_t k) const {
    if (!data) return 0;
    return component(data + i * stride + k * component_bytes(component_type), component_type,
                     normalized);
  }
};

class GltfReader {
 public:
  GltfReader(std::span<const char> bytes, const std::string& name, bool external_files)
      : bytes_(bytes), name_(name), external_files_(external_files) {}

  void read(Mesh& mesh, MeshSource& source);
  std::optional<GlbTriangleList> triangle_list();

 private:
  [[noreturn]] void fail(std::uint64_t offset, const std::string& problem) const {
    throw InputError(name_, byte_position(offset), problem);
  }
  [[noreturn]] void fail(const std::string& path, const std::string& problem) const {
    fail(json_offset_, path + ": " + problem);
  }

  void parse_container();
  void parse_document();
  template <class Instance>
  void walk_scene(Instance&& instance);
  std::string part_name(std::size_t node, std::size_t mesh_index) const;
  void check_output_room(const std::string& ppath, std::uint64_t vertices,
                         std::uint64_t corners) const;
  const Json& array(const char* key) const;
  const Json& at(const char* key, std::size_t index, const std::string& from) const;
  std::uint64_t uint_field(const Json& obj, const char* key, const std::string& path,
                           std::optional<std::uint64_t> fallback = std::nullopt) const;
  std::span<const char> buffer(std::size_t index);
  std::span<const char> buffer_view(std::size_t index, std::size_t* stride);
  AccessorView accessor(std::size_t index);
  AccessorView position_accessor(std::size_t index);
  void positions(const AccessorView& a, const Affine& world, std::vector<Vec3d>& vertices) const;
  void indices(std::size_t index, std::uint64_t vertex_count, std::vector<std::uint32_t>& out);
  Affine local_transform(std::size_t node) const;
  void add_instance(std::size_t node, std::size_t mesh_index, const Affine& world, Mesh& mesh,
                    MeshSource& source);

  std::span<const char> bytes_;
  const std::string& name_;
  bool external_files_;
  std::uint64_t json_offset_ = 0;
  std::span<const char> json_text_;
  std::optional<std::span<const char>> bin_chunk_;
  std::uint64_t bin_offset_ = 0;
  Json doc_;
  std::vector<std::optional<std::span<const char>>> buffers_;
  std::vector<std::vector<char>> decoded_;  // data: URI buffers
  std::vector<MappedFile> files_;           // external buffers
  std::uint64_t input_bytes_ = 0;           // the file and its buffers: bounds the output
  bool quantized_ = false;                  // KHR_mesh_quantization
  std::uint64_t skipped_primitives_ = 0;
  bool mirrored_warned_ = false;
  bool single_precision_ = false;       // some positions were float32
  std::vector<std::uint32_t> indices_;  // the current primitive's, reused
};

// v.reserve(n) growing geometrically, with huge pages advised for large arrays.
template <class T>
void grow(std::vector<T>& v, std::size_t n) {
  if (n > v.capacity()) reserve_huge(v, std::max(n, 2 * v.capacity()));
}

void GltfReader::parse_container() {
  if (bytes_.size() >= 4 && le32(bytes_.data()) == glb_magic) {
    // GLB: magic, version, length; then chunks of (length, type, data padded to 4 bytes).
    if (bytes_.size() < 20) fail(bytes_.size(), "GLB file too short for its header");
    if (le32(bytes_.data() + 4) != 2)
      fail(4, "GLB version " + std::to_string(le32(bytes_.data() + 4)) + " (only 2 is read)");
    const std::uint64_t length = le32(bytes_.data() + 8);
    if (length > bytes_.size())
      fail(8, "GLB length " + std::to_string(length) + " is past the end of the file (" +
                  std::to_string(bytes_.size()) + " bytes)");
    std::uint64_t at = 12;
    bool first = true;
    while (at + 8 <= length) {
      const std::uint64_t chunk = le32(bytes_.data() + at);
      const std::uint32_t type = le32(bytes_.data() + at + 4);
      if (chunk > length - at - 8)
        fail(at, "GLB chunk of " + std::to_string(chunk) + " bytes is past the end of the file");
      const std::span<const char> data = bytes_.subspan(at + 8, chunk);
      if (first) {
        if (type != glb_json_chunk) fail(at + 4, "the first GLB chunk is not JSON");
        json_text_ = data;
        json_offset_ = at + 8;
      } else if (type == glb_bin_chunk && !bin_chunk_) {
        bin_chunk_ = data;
        bin_offset_ = at + 8;
      }
      first = false;
      at += 8 + chunk;
    }
    if (first) fail(12, "GLB file without a JSON chunk");
  } else {
    json_text_ = bytes_;
  }
  try {
    doc_ = Json::parse(json_text_.begin(), json_text_.end());
  } catch (const Json::parse_error& e) {
    const std::uint64_t at = e.byte ? e.byte - 1 : 0;
    if (json_offset_ == 0 && at <= bytes_.size())
      throw InputError(name_, text_position(bytes_.data(), bytes_.data() + at),
                       "invalid JSON: " + std::string(e.what()));
    fail(json_offset_ + at, "invalid JSON: " + std::string(e.what()));
  } catch (const Json::exception& e) {
    // The parser's other refusals carry no position: a number beyond a double's range
    // (out_of_range 406) is reported at the start of the JSON.
    fail(json_offset_, "invalid JSON: " + std::string(e.what()));
  }
  if (!doc_.is_object()) fail(json_offset_, "the glTF JSON is not an object");
}

const Json& GltfReader::array(const char* key) const {
  static const Json empty = Json::array();
  const auto it = doc_.find(key);
  if (it == doc_.end()) return empty;
  if (!it->is_array()) fail(key, "not an array");
  return *it;
}

// doc[key][index], an object, or an error naming `from` (where the index was read).
const Json& GltfReader::at(const char* key, std::size_t index, const std::string& from) const {
  const Json& list = array(key);
  if (index >= list.size())
    fail(from, std::to_string(index) + " is not an index of " + key + " (" +
                   std::to_string(list.size()) + " entries)");
  if (!list[index].is_object())
    fail(std::string(key) + "[" + std::to_string(index) + "]", "not an object");
  return list[index];
}

std::uint64_t GltfReader::uint_field(const Json& obj, const char* key, const std::string& path,
                                     std::optional<std::uint64_t> fallback) const {
  const std::string where = path.empty() ? std::string(key) : path + "." + key;
  if (!obj.is_object()) fail(path, "not an object");
  const auto it = obj.find(key);
  if (it == obj.end()) {
    if (fallback) return *fallback;
    fail(where, "missing");
  }
  if (!it->is_number_unsigned()) fail(where, "not a non-negative whole number: " + it->dump());
  return it->get<std::uint64_t>();
}

// The bytes of a base64 text (RFC 4648, '=' padding optional), or nullopt where it is not base64.
std::optional<std::vector<char>> decode_base64(std::string_view text) {
  auto value = [](char c) -> int {
    if (c >= 'A' && c <= 'Z') return c - 'A';
    if (c >= 'a' && c <= 'z') return c - 'a' + 26;
    if (c >= '0' && c <= '9') return c - '0' + 52;
    if (c == '+' || c == '-') return 62;
    if (c == '/' || c == '_') return 63;
    return -1;
  };
  while (!text.empty() && text.back() == '=') text.remove_suffix(1);
  if (text.size() % 4 == 1) return std::nullopt;
  std::vector<char> out;
  out.reserve(text.size() / 4 * 3 + 2);
  std::uint32_t acc = 0;
  int bits = 0;
  for (char c : text) {
    const int v = value(c);
    if (v < 0) return std::nullopt;
    acc = (acc << 6) | static_cast<std::uint32_t>(v);
    bits += 6;
    if (bits >= 8) {
      bits -= 8;
      out.push_back(static_cast<char>((acc >> bits) & 0xFF));
    }
  }
  return out;
}

// A relative URI's path with its %XX escapes decoded, or nullopt for a bad escape.
std::optional<std::string> percent_decoded(std::string_view uri) {
  std::string out;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] != '%') {
      out += uri[i];
      continue;
    }
    auto hex = [](char c) -> int {
      if (c >= '0' && c <= '9') return c - '0';
      if (c >= 'a' && c <= 'f') return c - 'a' + 10;
      if (c >= 'A' && c <= 'F') return c - 'A' + 10;
      return -1;
    };
    if (i + 2 >= uri.size() || hex(uri[i + 1]) < 0 || hex(uri[i + 2]) < 0) return std::nullopt;
    out += static_cast<char>(hex(uri[i + 1]) * 16 + hex(uri[i + 2]));
    i += 2;
  }
  return out;
}

// Whether a relative path stays in its folder: not absolute, no '..' segment, no scheme, no NUL.
bool stays_in_folder(const std::string& path) {
  if (path.empty() || path[0] == '/' || path[0] == '\\') return false;
  if (path.find('\0') != std::string::npos || path.find(':') != std::string::npos) return false;
  std::size_t start = 0;
  for (;;) {
    const std::size_t end = path.find_first_of("/\\", start);
    if (path.substr(start, end - start) == "..") return false;
    if (end == std::string::npos) return true;
    start = end + 1;
  }
}

std::span<const char> GltfReader::buffer(std::size_t index) {
  const std::string path = "buffers[" + std::to_string(index) + "]";
  const Json& b = at("buffers", index, path);
  if (buffers_.size() <= index) buffers_.resize(array("buffers").size());
  if (buffers_[index]) return *buffers_[index];
  const std::uint64_t length = uint_field(b, "byteLength", path);
  std::span<const char> data;
  const auto uri = b.find("uri");
  if (uri == b.end()) {
    if (index != 0 || !bin_chunk_) fail(path, "no uri and no GLB binary chunk");
    data = *bin_chunk_;
  } else {
    if (!uri->is_string()) fail(path + ".uri", "not a string");
    const std::string& text = uri->get_ref<const std::string&>();
    if (text.rfind("data:", 0) == 0) {
      const std::size_t comma = text.find(',');
      if (comma == std::string::npos || text.substr(0, comma).find(";base64") == std::string::npos)
        fail(path + ".uri", "a data: URI that is not base64");
      auto bytes = decode_base64(std::string_view(text).substr(comma + 1));
      if (!bytes) fail(path + ".uri", "bad base64 data");
      decoded_.push_back(std::move(*bytes));
      data = {decoded_.back().data(), decoded_.back().size()};
    } else {
      if (!external_files_)
        fail(path + ".uri", "external buffer '" + text +
                                "' cannot be read here (no folder: only data: URIs and GLB)");
      const auto relative = percent_decoded(text);
      if (!relative || !stays_in_folder(*relative))
        fail(path + ".uri",
             "external buffer '" + text + "' is not a relative path inside the glTF file's folder");
      const std::size_t slash = name_.find_last_of('/');
      const std::string folder = slash == std::string::npos ? "" : name_.substr(0, slash + 1);
      try {
        files_.push_back(MappedFile::open(folder + *relative));
      } catch (const InputError& e) {
        fail(path + ".uri", e.what());
      }
      data = files_.back().bytes();
      input_bytes_ += data.size();
    }
  }
  if (length > data.size())
    fail(path + ".byteLength",
         std::to_string(length) + " bytes, but the data holds " + std::to_string(data.size()));
  buffers_[index] = data.first(length);
  return *buffers_[index];
}

std::span<const char> GltfReader::buffer_view(std::size_t index, std::size_t* stride) {
  const std::string path = "bufferViews[" + std::to_string(index) + "]";
  const Json& v = at("bufferViews", index, path);
  const std::span<const char> buf = buffer(uint_field(v, "buffer", path));
  const std::uint64_t offset = uint_field(v, "byteOffset", path, 0);
  const std::uint64_t length = uint_field(v, "byteLength", path);
  if (offset > buf.size() || length > buf.size() - offset)
    fail(path, "byteOffset " + std::to_string(offset) + " + byteLength " + std::to_string(length) +
                   " is past the end of its buffer (" + std::to_string(buf.size()) + " bytes)");
  if (stride) {
    *stride = uint_field(v, "byteStride", path, 0);
    if (*stride && (*stride < 4 || *stride > 252 || *stride % 4))
      fail(path + ".byteStride", std::to_string(*stride) + " (must be 4 to 252, a multiple of 4)");
  }
  return buf.subspan(offset, length);
}

AccessorView GltfReader::accessor(std::size_t index) {
  AccessorView a;
  a.path = "accessors[" + std::to_string(index) + "]";
  const Json& j = at("accessors", index, a.path);
  a.component_type = static_cast<int>(uint_field(j, "componentType", a.path));
  const std::size_t cbytes = component_bytes(a.component_type);
  if (!cbytes)
    fail(a.path + ".componentType", std::to_string(a.component_type) + " is not a glTF type");
  const auto type = j.find("type");
  if (type == j.end() || !type->is_string() ||
      !(a.components = type_components(type->get<std::string>())))
    fail(a.path + ".type", "missing or not SCALAR, VEC2, VEC3, VEC4 or MATn");
  if (const auto n = j.find("normalized"); n != j.end()) {
    if (!n->is_boolean()) fail(a.path + ".normalized", "not a boolean");
    a.normalized = n->get<bool>();
  }
  a.count = uint_field(j, "count", a.path);
  if (a.count == 0) fail(a.path + ".count", "0 (must be at least 1)");
  const std::size_t element = cbytes * a.components;
  const std::uint64_t offset = uint_field(j, "byteOffset", a.path, 0);
  if (j.contains("bufferView")) {
    std::size_t stride = 0;
    const std::span<const char> view = buffer_view(uint_field(j, "bufferView", a.path), &stride);
    if (stride && stride < element)
      fail(a.path, "byteStride " + std::to_string(stride) + " of its bufferView is shorter than " +
                       "an element (" + std::to_string(element) + " bytes)");
    a.stride = stride ? stride : element;
    // (count − 1) × stride + element bytes from byteOffset, checked without overflow.
    const std::uint64_t room = view.size() >= offset ? view.size() - offset : 0;
    if (offset > view.size() || room < element || (a.count - 1) > (room - element) / a.stride)
      fail(a.path + ".count",
           std::to_string(a.count) + " elements of " + std::to_string(element) + " bytes (stride " +
               std::to_string(a.stride) + ") from byteOffset " + std::to_string(offset) +
               " are past the end of its bufferView (" + std::to_string(view.size()) + " bytes)");
    a.data = view.data() + offset;
  } else if (a.count > input_bytes_) {
    // Zeros (then sparse values) with no bytes behind them: bounded by the input's size.
    fail(a.path + ".count",
         std::to_string(a.count) + " elements without a bufferView: more than the file describes");
  }
  if (const auto s = j.find("sparse"); s != j.end()) {
    const std::string sp = a.path + ".sparse";
    if (!s->is_object()) fail(sp, "not an object");
    const std::uint64_t n = uint_field(*s, "count", sp);
    if (n == 0 || n > a.count)
      fail(sp + ".count", std::to_string(n) + " (must be 1 to the accessor's count)");
    const auto idx = s->find("indices");
    const auto val = s->find("values");
    if (idx == s->end() || !idx->is_object()) fail(sp + ".indices", "missing");
    if (val == s->end() || !val->is_object()) fail(sp + ".values", "missing");
    const int itype = static_cast<int>(uint_field(*idx, "componentType", sp + ".indices"));
    if (itype != 5121 && itype != 5123 && itype != 5125)
      fail(sp + ".indices.componentType", std::to_string(itype) + " (must be 5121, 5123, 5125)");
    const std::size_t ibytes = component_bytes(itype);
    auto packed = [&](const Json& o, const std::string& p, std::size_t size) {
      const std::span<const char> view = buffer_view(uint_field(o, "bufferView", p), nullptr);
      const std::uint64_t off = uint_field(o, "byteOffset", p, 0);
      if (off > view.size() || n > (view.size() - off) / size)
        fail(p, std::to_string(n) + " elements of " + std::to_string(size) +
                    " bytes are past the end of its bufferView");
      return view.data() + off;
    };
    const char* ip = packed(*idx, sp + ".indices", ibytes);
    a.sparse_values = packed(*val, sp + ".values", element);
    a.sparse_indices.reserve(n);
    for (std::uint64_t k = 0; k < n; ++k) {
      const auto i = static_cast<std::uint64_t>(component(ip + k * ibytes, itype, false));
      if (i >= a.count || (k && i <= a.sparse_indices.back()))
        fail(sp + ".indices", "index " + std::to_string(i) + " at " + std::to_string(k) +
                                  " is not ascending below the count " + std::to_string(a.count));
      a.sparse_indices.push_back(i);
    }
  }
  return a;
}

AccessorView GltfReader::position_accessor(std::size_t index) {
  AccessorView a = accessor(index);
  if (a.components != 3) fail(a.path + ".type", "POSITION must be VEC3");
  if (a.component_type != 5126 && !quantized_)
    fail(a.path + ".componentType",
         "POSITION of component type " + std::to_string(a.component_type) +
             " needs the extension KHR_mesh_quantization (declared in extensionsUsed)");
  if (a.component_type == 5125) fail(a.path + ".componentType", "POSITION cannot be 5125");
  if (a.component_type == 5126) single_precision_ = true;
  return a;
}

// The accessor's positions placed by `world`, appended to `vertices` (its capacity reserved: no
// zero-filling pass before the values, which on a large mesh costs as much as the values).
void GltfReader::positions(const AccessorView& a, const Affine& world,
                           std::vector<Vec3d>& vertices) const {
  const std::size_t base = vertices.size();
  if (a.data && a.component_type == 5126) {
    // The common case straight from the file's bytes: float32 to double is exact.
    for (std::uint64_t i = 0; i < a.count; ++i) {
      float f[3];
      std::memcpy(f, a.data + i * a.stride, 12);
      if constexpr (std::endian::native == std::endian::big)
        for (float& x : f)
          x = std::bit_cast<float>(__builtin_bswap32(std::bit_cast<std::uint32_t>(x)));
      vertices.push_back({f[0], f[1], f[2]});
    }
  } else {
    for (std::uint64_t i = 0; i < a.count; ++i)
      vertices.push_back({a.get(i, 0), a.get(i, 1), a.get(i, 2)});
  }
  Vec3d* out = vertices.data() + base;
  const std::size_t cb = component_bytes(a.component_type);
  for (std::size_t k = 0; k < a.sparse_indices.size(); ++k) {
    const char* p = a.sparse_values + k * 3 * cb;
    out[a.sparse_indices[k]] = {component(p, a.component_type, a.normalized),
                                component(p + cb, a.component_type, a.normalized),
                                component(p + 2 * cb, a.component_type, a.normalized)};
  }
  for (std::uint64_t i = 0; i < a.count; ++i) {
    if (!is_finite(out[i])) fail(a.path, "element " + std::to_string(i) + " is not finite");
    if (!world.identity) {
      out[i] = world.apply(out[i]);
      if (!is_finite(out[i]))
        fail(a.path, "element " + std::to_string(i) + " is not finite once transformed");
    }
  }
}

void GltfReader::indices(std::size_t index, std::uint64_t vertex_count,
                         std::vector<std::uint32_t>& out) {
  const AccessorView a = accessor(index);
  if (a.components != 1) fail(a.path + ".type", "indices must be SCALAR");
  if (a.component_type != 5121 && a.component_type != 5123 && a.component_type != 5125)
    fail(a.path + ".componentType",
         std::to_string(a.component_type) + " (indices must be 5121, 5123 or 5125)");
  if (a.normalized) fail(a.path + ".normalized", "indices cannot be normalized");
  out.clear();
  out.reserve(a.count);
  if (a.data && a.component_type == 5125)
    for (std::uint64_t i = 0; i < a.count; ++i) out.push_back(le32(a.data + i * a.stride));
  else
    for (std::uint64_t i = 0; i < a.count; ++i)
      out.push_back(static_cast<std::uint32_t>(a.get(i, 0)));
  for (std::size_t k = 0; k < a.sparse_indices.size(); ++k)
    out[a.sparse_indices[k]] = static_cast<std::uint32_t>(component(
        a.sparse_values + k * component_bytes(a.component_type), a.component_type, false));
  for (std::uint64_t i = 0; i < a.count; ++i)
    if (out[i] >= vertex_count)
      fail(a.path, "index " + std::to_string(out[i]) + " at element " + std::to_string(i) +
                       " is not below the " + std::to_string(vertex_count) + " vertices");
}

Affine GltfReader::local_transform(std::size_t node) const {
  const std::string path = "nodes[" + std::to_string(node) + "]";
  const Json& n = array("nodes")[node];
  auto numbers = [&](const char* key, std::size_t size) -> std::optional<std::vector<double>> {
    const auto it = n.find(key);
    if (it == n.end()) return std::nullopt;
    if (!it->is_array() || it->size() != size)
      fail(path + "." + key, "not an array of " + std::to_string(size) + " numbers");
    std::vector<double> v;
    for (const Json& x : *it) {
      if (!x.is_number()) fail(path + "." + key, "not an array of numbers");
      v.push_back(x.get<double>());
      if (!std::isfinite(v.back())) fail(path + "." + key, "not finite");
    }
    return v;
  };
  Affine a;
  if (const auto m = numbers("matrix", 16)) {
    for (int col = 0; col < 4; ++col)
      for (int row = 0; row < 3; ++row) a.m[row][col] = (*m)[col * 4 + row];  // column-major
    if ((*m)[3] != 0 || (*m)[7] != 0 || (*m)[11] != 0 || (*m)[15] != 1)
      fail(path + ".matrix", "not an affine transform (last row must be 0 0 0 1)");
    a.identity = false;
    return a;
  }
  const auto t = numbers("translation", 3);
  const auto r = numbers("rotation", 4);
  const auto s = numbers("scale", 3);
  if (!t && !r && !s) return a;
  // T × R × S (glTF 2.0 §3.5.3); R from the quaternion (x, y, z, w), divided by its norm².
  double rot[3][3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  if (r) {
    const double x = (*r)[0], y = (*r)[1], z = (*r)[2], w = (*r)[3];
    const double n2 = x * x + y * y + z * z + w * w;
    if (!(n2 > 0)) fail(path + ".rotation", "a zero quaternion");
    const double k = 2 / n2;
    rot[0][0] = 1 - k * (y * y + z * z);
    rot[0][1] = k * (x * y - z * w);
    rot[0][2] = k * (x * z + y * w);
    rot[1][0] = k * (x * y + z * w);
    rot[1][1] = 1 - k * (x * x + z * z);
    rot[1][2] = k * (y * z - x * w);
    rot[2][0] = k * (x * z - y * w);
    rot[2][1] = k * (y * z + x * w);
    rot[2][2] = 1 - k * (x * x + y * y);
  }
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) a.m[i][j] = rot[i][j] * (s ? (*s)[j] : 1.0);
    a.m[i][3] = t ? (*t)[i] : 0.0;
  }
  a.identity = false;
  return a;
}

void GltfReader::add_instance(std::size_t node, std::size_t mesh_index, const Affine& world,
                              Mesh& mesh, MeshSource& source) {
  const std::string mpath = "meshes[" + std::to_string(mesh_index) + "]";
  const Json& m = at("meshes", mesh_index, "nodes[" + std::to_string(node) + "].mesh");
  const auto prims = m.find("primitives");
  if (prims == m.end() || !prims->is_array()) fail(mpath + ".primitives", "missing");
  const bool mirrored = world.determinant() < 0;
  if (mirrored && !mirrored_warned_) {
    mirrored_warned_ = true;
    source.warnings.push_back("glTF nodes[" + std::to_string(node) +
                              "]: a mirroring transform (negative determinant): its triangles' "
                              "winding is reversed to keep them facing outward");
  }
  MeshPart part;
  part.first_face = static_cast<std::uint32_t>(mesh.face_count());
  part.name = part_name(node, mesh_index);

  for (std::size_t p = 0; p < prims->size(); ++p) {
    const std::string ppath = mpath + ".primitives[" + std::to_string(p) + "]";
    const Json& prim = (*prims)[p];
    if (!prim.is_object()) fail(ppath, "not an object");
    const std::uint64_t mode = uint_field(prim, "mode", ppath, 4);
    if (mode > 6) fail(ppath + ".mode", std::to_string(mode) + " is not a glTF primitive mode");
    if (mode < 4) {
      ++skipped_primitives_;
      continue;
    }
    const auto attrs = prim.find("attributes");
    if (attrs == prim.end() || !attrs->is_object() || !attrs->contains("POSITION"))
      fail(ppath + ".attributes", "no POSITION");
    const AccessorView pa =
        position_accessor(uint_field(*attrs, "POSITION", ppath + ".attributes"));
    std::vector<std::uint32_t>& idx = indices_;
    if (prim.contains("indices")) {
      indices(uint_field(prim, "indices", ppath), pa.count, idx);
    } else {
      if (pa.count > max_vertices) fail(ppath, "too many vertices for 32-bit indices");
      idx.resize(pa.count);
      for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = static_cast<std::uint32_t>(i);
    }
    const std::uint64_t base = mesh.vertices.size();
    const std::uint64_t corners = mesh.corners.size() + 3 * idx.size();
    check_output_room(ppath, base + pa.count, corners);
    // Geometric growth: a mesh instanced many times must not be copied at every instance.
    grow(mesh.vertices, base + pa.count);
    positions(pa, world, mesh.vertices);
    grow(mesh.corners, corners);
    grow(mesh.face_offsets, mesh.face_offsets.size() + idx.size() / 3 + idx.size());
    auto triangle = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
      if (mirrored) std::swap(b, c);
      const auto o = static_cast<std::uint32_t>(base);
      mesh.corners.insert(mesh.corners.end(), {a + o, b + o, c + o});
      mesh.face_offsets.push_back(static_cast<std::uint32_t>(mesh.corners.size()));
    };
    if (mode == 4) {
      if (idx.size() % 3)
        fail(ppath, std::to_string(idx.size()) + " vertices: TRIANGLES needs a multiple of 3");
      // The common case in one pass over flat arrays.
      const std::size_t c0 = mesh.corners.size();
      const auto o = static_cast<std::uint32_t>(base);
      const std::size_t second = mirrored ? 2 : 1, third = mirrored ? 1 : 2;
      for (std::size_t i = 0; i < idx.size(); i += 3) {
        mesh.corners.push_back(idx[i] + o);
        mesh.corners.push_back(idx[i + second] + o);
        mesh.corners.push_back(idx[i + third] + o);
        mesh.face_offsets.push_back(static_cast<std::uint32_t>(c0 + i + 3));
      }
    } else if (mode == 5) {
      // Strip: triangle i is (i, i+1+i%2, i+2−i%2) (glTF 2.0 §3.7.2.1); the degenerate
      // triangles that join strips (a repeated index) are not faces and are dropped.
      for (std::size_t i = 0; i + 2 < idx.size(); ++i) {
        const std::uint32_t a = idx[i], b = idx[i + 1 + i % 2], c = idx[i + 2 - i % 2];
        if (a != b && b != c && a != c) triangle(a, b, c);
      }
    } else {
      // Fan: triangle i is (i+1, i+2, 0).
      for (std::size_t i = 0; i + 2 < idx.size(); ++i) triangle(idx[i + 1], idx[i + 2], idx[0]);
    }
  }
  part.face_count = static_cast<std::uint32_t>(mesh.face_count() - part.first_face);
  source.parts.push_back(std::move(part));
}

// The name of the part that node `node` instancing meshes[mesh_index] becomes.
std::string GltfReader::part_name(std::size_t node, std::size_t mesh_index) const {
  const Json& n = array("nodes")[node];
  const Json& m = array("meshes")[mesh_index];
  if (n.contains("name") && n["name"].is_string()) return n["name"].get<std::string>();
  if (m.contains("name") && m["name"].is_string()) return m["name"].get<std::string>();
  return "nodes[" + std::to_string(node) + "]";
}

// Fails at `ppath` when a mesh of `vertices` vertices and `corners` corners (those read so far and
// the next primitive's) is more than this reader accepts: the output is bounded by the input
// (instancing may repeat a mesh, not without end) and by the 32-bit indices.
void GltfReader::check_output_room(const std::string& ppath, std::uint64_t vertices,
                                   std::uint64_t corners) const {
  const std::uint64_t max_output =
      std::max<std::uint64_t>(std::uint64_t{1} << 20, 16 * input_bytes_);
  if (vertices > max_vertices || vertices > max_output || corners > max_vertices ||
      corners > max_output * 3)
    fail(ppath, "the instanced meshes hold more vertices than this reader accepts (" +
                    std::to_string(max_output) + ", 16 per byte of input)");
}

// The container and the document's header: the JSON parsed, its glTF version and the extensions
// it requires checked.
void GltfReader::parse_document() {
  input_bytes_ = bytes_.size();
  parse_container();
  const auto asset = doc_.find("asset");
  if (asset == doc_.end() || !asset->is_object() || !asset->contains("version") ||
      !(*asset)["version"].is_string())
    fail("asset.version", "missing: not a glTF document");
  const std::string version = (*asset)["version"].get<std::string>();
  if (version.rfind("2.", 0) != 0) fail("asset.version", "'" + version + "' (only 2.x is read)");
  for (const char* key : {"extensionsUsed", "extensionsRequired"}) {
    for (const Json& e : array(key)) {
      if (!e.is_string()) continue;
      const std::string ext = e.get<std::string>();
      if (ext == "KHR_mesh_quantization") quantized_ = true;
      if (std::string(key) == "extensionsRequired" &&
          (ext == "KHR_draco_mesh_compression" || ext == "EXT_meshopt_compression" ||
           ext == "EXT_mesh_gpu_instancing"))
        fail(key, "the extension " + ext + " is required and not supported");
    }
  }
  for (const Json& b : array("buffers")) (void)b;  // validated when used
}

// Calls instance(node, mesh index, world transform) for each node of the scene that instances a
// mesh, depth first in the order of the scene's roots and of each node's children.
template <class Instance>
void GltfReader::walk_scene(Instance&& instance) {
  const Json& nodes = array("nodes");
  // The roots: the default scene's nodes, else every node that is no node's child. Each node has
  // at most one parent (glTF 2.0 §3.5.1): a second use, or a cycle, is an error.
  std::vector<std::int64_t> parent(nodes.size(), -1);
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    const std::string path = "nodes[" + std::to_string(i) + "]";
    if (!nodes[i].is_object()) fail(path, "not an object");
    const auto ch = nodes[i].find("children");
    if (ch == nodes[i].end()) continue;
    if (!ch->is_array()) fail(path + ".children", "not an array");
    for (std::size_t k = 0; k < ch->size(); ++k) {
      const std::string cpath = path + ".children[" + std::to_string(k) + "]";
      if (!(*ch)[k].is_number_unsigned() || (*ch)[k].get<std::uint64_t>() >= nodes.size())
        fail(cpath, "not a node index");
      const auto c = (*ch)[k].get<std::size_t>();
      if (parent[c] >= 0)
        fail(cpath, "node " + std::to_string(c) + " already has a parent (nodes[" +
                        std::to_string(parent[c]) + "]): a node is used once in a hierarchy");
      if (c == i) fail(cpath, "a node cannot be its own child");
      parent[c] = static_cast<std::int64_t>(i);
    }
  }
  std::vector<std::size_t> roots;
  if (doc_.contains("scene")) {
    const std::size_t s = uint_field(doc_, "scene", "");
    const Json& scene = at("scenes", s, "scene");
    if (const auto sn = scene.find("nodes"); sn != scene.end()) {
      if (!sn->is_array()) fail("scenes[" + std::to_string(s) + "].nodes", "not an array");
      for (std::size_t k = 0; k < sn->size(); ++k) {
        const std::string path =
            "scenes[" + std::to_string(s) + "].nodes[" + std::to_string(k) + "]";
        if (!(*sn)[k].is_number_unsigned() || (*sn)[k].get<std::uint64_t>() >= nodes.size())
          fail(path, "not a node index");
        const auto r = (*sn)[k].get<std::size_t>();
        if (parent[r] >= 0)
          fail(path, "node " + std::to_string(r) + " is a child of nodes[" +
                         std::to_string(parent[r]) + "], not a root");
        roots.push_back(r);
      }
    }
  } else {
    for (std::size_t i = 0; i < nodes.size(); ++i)
      if (parent[i] < 0) roots.push_back(i);
  }
  // Depth first without recursion (a hostile file may chain a million nodes); each node is
  // reached at most once, so a cycle (whose nodes all have parents) is never reached from a root.
  std::vector<char> visited(nodes.size(), 0);
  std::vector<std::pair<std::size_t, Affine>> stack;
  for (auto it = roots.rbegin(); it != roots.rend(); ++it) stack.push_back({*it, Affine{}});
  while (!stack.empty()) {
    auto [node, parent_world] = stack.back();
    stack.pop_back();
    if (visited[node])
      fail("nodes[" + std::to_string(node) + "]", "used twice in the scene's hierarchy");
    visited[node] = 1;
    const Affine world = compose(parent_world, local_transform(node));
    const Json& n = nodes[node];
    if (n.contains("mesh"))
      instance(node, uint_field(n, "mesh", "nodes[" + std::to_string(node) + "]"), world);
    if (const auto ch = n.find("children"); ch != n.end())
      for (auto c = ch->rbegin(); c != ch->rend(); ++c)
        stack.push_back({c->get<std::size_t>(), world});
  }
}

void GltfReader::read(Mesh& mesh, MeshSource& source) {
  parse_document();
  walk_scene([&](std::size_t node, std::size_t mesh_index, const Affine& world) {
    add_instance(node, mesh_index, world, mesh, source);
  });
  if (skipped_primitives_)
    source.warnings.push_back("glTF: " + std::to_string(skipped_primitives_) +
                              " primitives of points or lines (modes 0 to 3) skipped: no faces");
  source.single_precision = single_precision_;
  source.unit =
      LengthUnit::meter;  // glTF 2.0 §3.4: "the units for all linear distances are meters"
}

// Whether the transform moves no point: the identity, or a matrix of its exact ones and zeros (a
// node that writes out an identity matrix, a zero translation, a unit rotation or scale), under
// which the reader copies each coordinate's value.
bool moves_nothing(const Affine& a) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j)
      if (a.m[i][j] != (i == j ? 1.0 : 0.0)) return false;
  return true;
}

std::optional<GlbTriangleList> GltfReader::triangle_list() {
  if (bytes_.size() < 4 || le32(bytes_.data()) != glb_magic) return std::nullopt;
  parse_document();
  if (!bin_chunk_) return std::nullopt;
  struct Instance {
    std::size_t node, mesh;
    Affine world;
  };
  std::vector<Instance> instances;
  walk_scene([&](std::size_t node, std::size_t mesh_index, const Affine& world) {
    instances.push_back({node, mesh_index, world});
  });
  if (instances.size() != 1 || !moves_nothing(instances[0].world)) return std::nullopt;
  const std::size_t node = instances[0].node, mesh_index = instances[0].mesh;
  const std::string mpath = "meshes[" + std::to_string(mesh_index) + "]";
  const Json& m = at("meshes", mesh_index, "nodes[" + std::to_string(node) + "].mesh");
  const auto prims = m.find("primitives");
  if (prims == m.end() || !prims->is_array() || prims->size() != 1) return std::nullopt;
  const std::string ppath = mpath + ".primitives[0]";
  const Json& prim = (*prims)[0];
  if (!prim.is_object() || prim.contains("indices") || uint_field(prim, "mode", ppath, 4) != 4)
    return std::nullopt;
  const auto attrs = prim.find("attributes");
  if (attrs == prim.end() || !attrs->is_object() || !attrs->contains("POSITION"))
    return std::nullopt;
  // The accessor resolved and bounds-checked as the reader resolves it.
  const AccessorView a = position_accessor(uint_field(*attrs, "POSITION", ppath + ".attributes"));
  if (a.component_type != 5126 || a.normalized || !a.data || a.stride != 12 || a.sparse_values ||
      a.count % 3)
    return std::nullopt;
  const auto first = reinterpret_cast<std::uintptr_t>(a.data);
  const auto chunk = reinterpret_cast<std::uintptr_t>(bin_chunk_->data());
  if (first < chunk || first - chunk > bin_chunk_->size() ||
      a.count > (bin_chunk_->size() - (first - chunk)) / 12)
    return std::nullopt;  // a buffer of its own (a data: URI), not the BIN chunk
  check_output_room(ppath, a.count, 3 * a.count);
  return GlbTriangleList{static_cast<std::uint64_t>(a.data - bytes_.data()), a.count / 3,
                         part_name(node, mesh_index)};
}

}  // namespace

std::optional<GlbTriangleList> glb_triangle_list(std::span<const char> bytes,
                                                 const std::string& name) {
  try {
    return GltfReader(bytes, name, false).triangle_list();
  } catch (const InputError&) {
    return std::nullopt;  // read_gltf reports it
  }
}

void read_gltf(std::span<const char> bytes, const std::string& name, Mesh& mesh, MeshSource& source,
               bool external_files) {
  source.format =
      bytes.size() >= 4 && le32(bytes.data()) == glb_magic ? MeshFormat::glb : MeshFormat::gltf;
  GltfReader(bytes, name, external_files).read(mesh, source);
}

}  // namespace pgamesh::detail
