// The 3MF reader (3MF core specification 1.x, docs/formats.md "3MF"): the OPC zip package
// (zip_package.hpp), its root relationships to the 3D model part, and the model XML (pugixml,
// parsed in place). The mesh read is the whole build: every build item's object with its
// components, placed by the composed transforms in double precision; each build item is a MeshPart.
#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <optional>
#include <pugixml.hpp>
#include <set>
#include <unordered_map>

#include "detail/memory/huge_pages.hpp"
#include "io/affine.hpp"
#include "io/readers.hpp"
#include "io/text_cursor.hpp"
#include "io/xml_arena.hpp"
#include "io/zip_package.hpp"
#include "pgamesh/core/input_error.hpp"
#include "pgamesh/core/number_text.hpp"

namespace pgamesh::detail {

namespace {

constexpr std::string_view model_relationship =
    "http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel";

// A 3MF transform is the 4×3 matrix "m00 m01 m02 m10 m11 m12 m20 m21 m22 m30 m31 m32" acting on
// row vectors, p' = [x y z 1] · M (3MF core specification, §3.3 "3D Matrices"): as an Affine
// (columns acting on column vectors), row i is (m0i, m1i, m2i, m3i). No attribute is the identity.
Affine affine_from_3mf(const std::array<double, 12>& a) {
  Affine t;
  t.identity = false;
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < 3; ++k) t.m[i][k] = a[3 * k + i];
    t.m[i][3] = a[9 + i];
  }
  return t;
}

// `first`, then `second`; nullopt is the identity.
std::optional<Affine> then(const std::optional<Affine>& first,
                           const std::optional<Affine>& second) {
  if (!first) return second;
  if (!second) return first;
  return compose(*second, *first);
}

std::string_view local_name(const char* name) {
  const std::string_view s = name;
  const std::size_t colon = s.find(':');
  return colon == std::string_view::npos ? s : s.substr(colon + 1);
}

// An XML part of the package, parsed in place. Errors name the package file, the part and the
// line:column in the part: the in-place parse overwrites delimiters with NULs, so the position is
// counted in a fresh copy of the part, inflated again only when an error is reported.
class XmlPart {
 public:
  XmlPart(const ZipPackage& package, const std::string& file, std::string part)
      : package_(package), file_(file), part_(std::move(part)), text_(package.read(part_)) {
    const pugi::xml_parse_result r = doc_.load_buffer_inplace(
        text_.begin(), text_.size, pugi::parse_escapes, pugi::encoding_utf8);
    if (!r)
      fail_at(static_cast<std::size_t>(r.offset), std::string("malformed XML: ") + r.description());
  }

  const pugi::xml_document& doc() const { return doc_; }
  const std::string& part() const { return part_; }

  // The offset of a node's name or an attribute's value in the part (both point into the text).
  std::size_t offset_of(const char* at) const {
    const char* begin = text_.begin();
    return at >= begin && at <= text_.end() ? static_cast<std::size_t>(at - begin) : 0;
  }

  [[noreturn]] void fail_at(std::size_t offset, const std::string& problem) const {
    fail_in(package_, file_, part_, offset, problem);
  }
  [[noreturn]] void fail(const pugi::xml_node& n, const std::string& problem) const {
    fail_at(offset_of(n.name()), "<" + std::string(n.name()) + ">: " + problem);
  }
  [[noreturn]] void fail(const pugi::xml_node& n, const pugi::xml_attribute& a,
                         const std::string& problem) const {
    fail_at(offset_of(a.value()), "<" + std::string(n.name()) + " " + a.name() + ">: " + problem);
  }

  [[noreturn]] static void fail_in(const ZipPackage& package, const std::string& file,
                                   const std::string& part, std::size_t offset,
                                   const std::string& problem) {
    const PartBytes raw = package.read(part);
    const InputPosition where =
        text_position(raw.begin(), raw.begin() + std::min(offset, raw.size));
    throw InputError(file, where, "in part /" + part + ": " + problem);
  }

 private:
  const ZipPackage& package_;
  const std::string& file_;
  std::string part_;
  XmlArena arena_;  // before the tree: it outlives it
  PartBytes text_;
  pugi::xml_document doc_;
};

double number(const XmlPart& x, const pugi::xml_node& n, const pugi::xml_attribute& a) {
  double v = 0;
  const NumberFault f = read_number(a.value(), v);
  if (f != NumberFault::none) x.fail(n, a, std::string(describe(f)) + " '" + a.value() + "'");
  return v;
}

std::uint32_t index_value(const XmlPart& x, const pugi::xml_node& n, const pugi::xml_attribute& a) {
  const char* s = a.value();
  const std::size_t len = std::strlen(s);
  std::uint32_t v = 0;
  const auto [stop, ec] = std::from_chars(s, s + len, v);
  if (len == 0 || ec != std::errc{} || stop != s + len)
    x.fail(n, a, std::string("malformed index '") + s + "' (a non-negative integer below 2^32)");
  return v;
}

std::uint32_t required_index(const XmlPart& x, const pugi::xml_node& n, const char* name) {
  const pugi::xml_attribute a = n.attribute(name);
  if (!a) x.fail(n, std::string("missing attribute ") + name);
  return index_value(x, n, a);
}

std::optional<Affine> transform_of(const XmlPart& x, const pugi::xml_node& n) {
  const pugi::xml_attribute a = n.attribute("transform");
  if (!a) return std::nullopt;
  std::array<double, 12> m{};
  const char* p = a.value();
  const char* end = p + std::strlen(p);
  std::size_t k = 0;
  for (;;) {
    while (p < end && (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r')) ++p;
    if (p == end) break;
    const char* token = p;
    while (p < end && !(*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r')) ++p;
    if (k == 12) x.fail(n, a, "more than 12 numbers in the transform");
    const std::string word(token, p);
    const NumberFault f = read_number(word, m[k]);
    if (f != NumberFault::none)
      x.fail(n, a, std::string(describe(f)) + " '" + word + "' in the transform");
    ++k;
  }
  if (k != 12)
    x.fail(n, a, "a transform has 12 numbers (m00 m01 m02 m10 … m32), not " + std::to_string(k));
  return affine_from_3mf(m);
}

struct Component {
  std::uint32_t object_id = 0;
  std::optional<Affine> transform;
  std::size_t offset = 0;  // in the model part, for errors
};

struct Object {
  std::uint32_t id = 0;
  std::string name;
  std::vector<Vec3d> vertices;
  std::vector<std::uint32_t> triangles;  // three indices each
  std::vector<Component> components;
  std::vector<std::size_t> children;  // object indices of the components, resolved
};

struct BuildItem {
  std::uint32_t object_id = 0;
  std::optional<Affine> transform;
  std::size_t offset = 0;
  std::size_t object = 0;  // resolved
};

// What the reader ignores, one warning per kind (docs/formats.md, "3MF").
struct Ignored {
  std::set<std::string> kinds;
  void note(std::string_view element) {
    if (element == "basematerials" || element == "compositematerials" ||
        element == "multiproperties")
      kinds.insert("materials (basematerials, compositematerials, multiproperties) ignored");
    else if (element == "colorgroup")
      kinds.insert("colours (colorgroup) ignored");
    else if (element == "texture2d" || element == "texture2dgroup")
      kinds.insert("textures (texture2d, texture2dgroup) ignored");
    else if (element == "slicestack")
      kinds.insert("slices (slice extension) ignored");
    else if (element == "beamlattice")
      kinds.insert(
          "beam lattice ignored: its beams have no volume in the core mesh, so the figures are "
          "those of the triangles only");
    else
      kinds.insert("unknown element <" + std::string(element) + "> ignored");
  }
};

std::size_t element_count(const pugi::xml_node& parent) {
  std::size_t n = 0;
  for (pugi::xml_node c = parent.first_child(); c; c = c.next_sibling()) ++n;
  return n;
}

void read_mesh_element(const XmlPart& x, const pugi::xml_node& mesh, Object& o, Ignored& ignored) {
  for (pugi::xml_node part = mesh.first_child(); part; part = part.next_sibling()) {
    if (part.type() != pugi::node_element) continue;
    const std::string_view name = part.name();
    if (name == "vertices") {
      reserve_huge(o.vertices, o.vertices.size() + element_count(part));
      for (pugi::xml_node v = part.first_child(); v; v = v.next_sibling()) {
        if (v.type() != pugi::node_element) continue;
        if (std::strcmp(v.name(), "vertex") != 0) x.fail(v, "unexpected element in <vertices>");
        double xyz[3] = {0, 0, 0};
        unsigned seen = 0;
        for (pugi::xml_attribute a = v.first_attribute(); a; a = a.next_attribute()) {
          const char* an = a.name();
          if (an[0] >= 'x' && an[0] <= 'z' && an[1] == '\0') {
            xyz[an[0] - 'x'] = number(x, v, a);
            seen |= 1u << (an[0] - 'x');
          }
        }
        if (seen != 7) x.fail(v, "missing coordinate (x, y and z are required)");
        o.vertices.push_back({xyz[0], xyz[1], xyz[2]});
      }
    } else if (name == "triangles") {
      reserve_huge(o.triangles, o.triangles.size() + 3 * element_count(part));
      for (pugi::xml_node t = part.first_child(); t; t = t.next_sibling()) {
        if (t.type() != pugi::node_element) continue;
        if (std::strcmp(t.name(), "triangle") != 0) x.fail(t, "unexpected element in <triangles>");
        std::uint32_t v[3] = {0, 0, 0};
        unsigned seen = 0;
        for (pugi::xml_attribute a = t.first_attribute(); a; a = a.next_attribute()) {
          const char* an = a.name();
          if (an[0] == 'v' && an[1] >= '1' && an[1] <= '3' && an[2] == '\0') {
            const int k = an[1] - '1';
            v[k] = index_value(x, t, a);
            if (v[k] >= o.vertices.size())
              x.fail(t, a,
                     "vertex index " + std::to_string(v[k]) + " out of range (the object has " +
                         std::to_string(o.vertices.size()) + " vertices, indices from 0)");
            seen |= 1u << k;
          }
        }
        if (seen != 7) x.fail(t, "missing vertex index (v1, v2 and v3 are required)");
        if (v[0] == v[1] || v[1] == v[2] || v[0] == v[2])
          x.fail(t, "repeated vertex index (" + std::to_string(v[0]) + ", " + std::to_string(v[1]) +
                        ", " + std::to_string(v[2]) + "): a triangle has three distinct vertices");
        o.triangles.insert(o.triangles.end(), v, v + 3);
      }
    } else {
      ignored.note(local_name(part.name()));
    }
  }
}

// The model part named by the package's root relationships: exactly one relationship of the 3D
// model type, internal, to a part that exists.
std::string model_part_name(const ZipPackage& package, const std::string& file) {
  if (!package.has("_rels/.rels"))
    throw InputError(file, byte_position(0),
                     "no _rels/.rels in the package: not a 3MF (OPC) package, no model part");
  const XmlPart rels(package, file, "_rels/.rels");
  std::optional<std::string> target;
  for (pugi::xml_node r = rels.doc().document_element().first_child(); r; r = r.next_sibling()) {
    if (r.type() != pugi::node_element || local_name(r.name()) != "Relationship") continue;
    if (model_relationship != r.attribute("Type").value()) continue;
    if (std::string_view(r.attribute("TargetMode").value()) == "External")
      rels.fail(r,
                "the 3D model relationship targets an external resource (TargetMode=\"External\"), "
                "which is not read");
    if (target)
      rels.fail(r, "more than one 3D model relationship: a 3MF package has one model start part");
    std::string t = r.attribute("Target").value();
    if (t.empty()) rels.fail(r, "the 3D model relationship has no Target");
    target = t.front() == '/' ? t.substr(1) : t;  // relative to the package root
  }
  if (!target)
    throw InputError(file, byte_position(0),
                     "missing model part: _rels/.rels has no relationship of type " +
                         std::string(model_relationship));
  if (!package.has(*target))
    throw InputError(
        file, byte_position(0),
        "missing model part: _rels/.rels names /" + *target + ", which the package does not hold");
  return *target;
}

}  // namespace

void read_3mf(std::span<const char> bytes, const std::string& name, Mesh& mesh,
              MeshSource& source) {
  source.format = MeshFormat::threemf;
  const ZipPackage package(bytes, name);
  const std::string part = model_part_name(package, name);

  std::vector<Object> objects;
  std::vector<BuildItem> items;
  Ignored ignored;
  {
    const XmlPart x(package, name, part);
    const pugi::xml_node model = x.doc().document_element();
    if (!model || local_name(model.name()) != "model")
      x.fail_at(0, "the root element is not <model>");
    const pugi::xml_attribute unit = model.attribute("unit");
    if (!unit) {
      source.unit = LengthUnit::millimeter;  // the specification's default
    } else if (const auto u = unit_from_name(unit.value());
               u && std::string_view(unit.value()).size() > 2) {  // not pgamesh's short names
      source.unit = *u;
    } else {
      x.fail(model, unit,
             std::string("unknown unit '") + unit.value() +
                 "' (micron, millimeter, centimeter, inch, foot or meter)");
    }
    std::unordered_map<std::uint32_t, std::size_t> resource_offsets;
    for (pugi::xml_node section = model.first_child(); section; section = section.next_sibling()) {
      if (section.type() != pugi::node_element) continue;
      const std::string_view section_name = section.name();
      if (section_name == "resources") {
        for (pugi::xml_node r = section.first_child(); r; r = r.next_sibling()) {
          if (r.type() != pugi::node_element) continue;
          if (const pugi::xml_attribute id = r.attribute("id")) {
            const std::uint32_t value = index_value(x, r, id);
            if (!resource_offsets.emplace(value, x.offset_of(id.value())).second)
              x.fail(r, id, "duplicate resource id " + std::to_string(value));
          }
          if (std::strcmp(r.name(), "object") != 0) {
            ignored.note(local_name(r.name()));
            continue;
          }
          Object o;
          o.id = required_index(x, r, "id");
          o.name = r.attribute("name").value();
          if (o.name.empty()) o.name = "object " + std::to_string(o.id);
          if (r.attribute("pid")) ignored.note("basematerials");
          for (pugi::xml_node c = r.first_child(); c; c = c.next_sibling()) {
            if (c.type() != pugi::node_element) continue;
            const std::string_view cn = c.name();
            if (cn == "mesh") {
              read_mesh_element(x, c, o, ignored);
            } else if (cn == "components") {
              for (pugi::xml_node k = c.first_child(); k; k = k.next_sibling()) {
                if (k.type() != pugi::node_element) continue;
                if (std::strcmp(k.name(), "component") != 0)
                  x.fail(k, "unexpected element in <components>");
                if (k.attribute("p:path"))
                  x.fail(k, "a component in another model part (production extension) is not read");
                o.components.push_back(
                    {required_index(x, k, "objectid"), transform_of(x, k), x.offset_of(k.name())});
              }
            } else if (local_name(c.name()) != "metadatagroup") {
              ignored.note(local_name(c.name()));
            }
          }
          if (r.attribute("slicestackid")) ignored.note("slicestack");
          objects.push_back(std::move(o));
        }
      } else if (section_name == "build") {
        for (pugi::xml_node it = section.first_child(); it; it = it.next_sibling()) {
          if (it.type() != pugi::node_element) continue;
          if (std::strcmp(it.name(), "item") != 0) continue;
          if (it.attribute("p:path"))
            x.fail(it, "a build item in another model part (production extension) is not read");
          items.push_back(
              {required_index(x, it, "objectid"), transform_of(x, it), x.offset_of(it.name()), 0});
        }
      } else if (section_name != "metadata") {
        ignored.note(local_name(section.name()));
      }
    }
  }  // the XML text and its tree are freed here: only the objects are kept

  auto fail = [&](std::size_t offset, const std::string& problem) {
    XmlPart::fail_in(package, name, part, offset, problem);
  };
  std::unordered_map<std::uint32_t, std::size_t> by_id;
  for (std::size_t i = 0; i < objects.size(); ++i) by_id.emplace(objects[i].id, i);
  for (Object& o : objects)
    for (const Component& c : o.components) {
      const auto it = by_id.find(c.object_id);
      if (it == by_id.end())
        fail(c.offset, "<component>: objectid " + std::to_string(c.object_id) +
                           " names no object of the model");
      o.children.push_back(it->second);
    }
  for (BuildItem& item : items) {
    const auto it = by_id.find(item.object_id);
    if (it == by_id.end())
      fail(item.offset,
           "<item>: objectid " + std::to_string(item.object_id) + " names no object of the model");
    item.object = it->second;
  }

  // Component cycles, and how many vertices and triangles each object expands to (saturating), by
  // an iterative depth-first search: an instancing chain may be as deep as there are objects.
  constexpr std::uint64_t saturated = std::numeric_limits<std::uint64_t>::max() / 4;
  std::vector<std::uint64_t> vertex_total(objects.size()), triangle_total(objects.size());
  {
    std::vector<unsigned char> state(objects.size(), 0);    // 0 new, 1 on the path, 2 done
    std::vector<std::pair<std::size_t, std::size_t>> path;  // object, next component
    for (std::size_t root = 0; root < objects.size(); ++root) {
      if (state[root]) continue;
      path.push_back({root, 0});
      state[root] = 1;
      while (!path.empty()) {
        auto& [o, next] = path.back();
        if (next < objects[o].children.size()) {
          const std::size_t child = objects[o].children[next];
          const std::size_t component = next++;
          if (state[child] == 1)
            fail(objects[o].components[component].offset,
                 "<component>: component cycle: object " + std::to_string(objects[o].id) +
                     " contains itself through object " + std::to_string(objects[child].id));
          if (state[child] == 0) {
            state[child] = 1;
            path.push_back({child, 0});
          }
          continue;
        }
        std::uint64_t v = objects[o].vertices.size(), t = objects[o].triangles.size() / 3;
        for (std::size_t child : objects[o].children) {
          v = std::min(saturated, v + vertex_total[child]);
          t = std::min(saturated, t + triangle_total[child]);
        }
        vertex_total[o] = v;
        triangle_total[o] = t;
        state[o] = 2;
        path.pop_back();
      }
    }
  }

  // The build, expanded: bounded by the 32-bit indices of Mesh and by the size of the archive, so
  // that a small file cannot instance itself into gigabytes (an "instancing bomb").
  std::uint64_t build_vertices = 0, build_triangles = 0;
  for (const BuildItem& item : items) {
    build_vertices = std::min(saturated, build_vertices + vertex_total[item.object]);
    build_triangles = std::min(saturated, build_triangles + triangle_total[item.object]);
  }
  const std::uint64_t expansion_limit = 64 * std::uint64_t{bytes.size()} + (std::uint64_t{1} << 22);
  if (build_vertices > max_vertices || 3 * build_triangles > 0xFFFFFFFFull ||
      build_vertices + build_triangles > expansion_limit)
    throw InputError(name, byte_position(0),
                     "the build expands to " + std::to_string(build_vertices) + " vertices and " +
                         std::to_string(build_triangles) +
                         " triangles: beyond the limit for an archive of this size (" +
                         std::to_string(expansion_limit) +
                         " vertices + triangles) or the 32-bit indices");
  reserve_huge(mesh.vertices, build_vertices);
  reserve_huge(mesh.corners, 3 * build_triangles);
  reserve_huge(mesh.face_offsets, build_triangles + 1);

  struct Instance {
    std::size_t object;
    std::optional<Affine> transform;
  };
  std::vector<Instance> stack;
  for (std::size_t i = 0; i < items.size(); ++i) {
    const BuildItem& item = items[i];
    const std::uint32_t first_face = static_cast<std::uint32_t>(mesh.face_count());
    bool mirrored = false;
    stack.push_back({item.object, item.transform});
    while (!stack.empty()) {
      const Instance in = std::move(stack.back());
      stack.pop_back();
      const Object& o = objects[in.object];
      const bool flip = in.transform && in.transform->determinant() < 0;
      mirrored |= flip && !o.triangles.empty();
      const auto base = static_cast<std::uint32_t>(mesh.vertices.size());
      if (in.transform) {
        for (const Vec3d& p : o.vertices) {
          const Vec3d q = in.transform->apply(p);
          if (!is_finite(q))
            fail(item.offset, "<item>: the transforms take a vertex of object " +
                                  std::to_string(o.id) + " beyond double range");
          mesh.vertices.push_back(q);
        }
      } else {
        mesh.vertices.insert(mesh.vertices.end(), o.vertices.begin(), o.vertices.end());
      }
      for (std::size_t t = 0; t < o.triangles.size(); t += 3) {
        const std::uint32_t* v = o.triangles.data() + t;
        // A mirror reverses orientation: the winding is flipped so the instance stays outward.
        if (flip)
          mesh.corners.insert(mesh.corners.end(), {base + v[0], base + v[2], base + v[1]});
        else
          mesh.corners.insert(mesh.corners.end(), {base + v[0], base + v[1], base + v[2]});
        mesh.face_offsets.push_back(static_cast<std::uint32_t>(mesh.corners.size()));
      }
      for (std::size_t k = o.components.size(); k-- > 0;)
        stack.push_back({o.children[k], then(o.components[k].transform, in.transform)});
    }
    const Object& top = objects[item.object];
    source.parts.push_back(
        {top.name, first_face, static_cast<std::uint32_t>(mesh.face_count() - first_face)});
    if (mirrored)
      source.warnings.push_back("build item " + std::to_string(i + 1) + " (" + top.name +
                                ") is mirrored (a transform with negative determinant): the "
                                "winding of its faces was flipped so that its volume stays "
                                "positive");
  }
  if (items.empty()) source.warnings.push_back("the 3MF build has no items: the mesh is empty");
  source.warnings.insert(source.warnings.end(), ignored.kinds.begin(), ignored.kinds.end());
}

}  // namespace pgamesh::detail
