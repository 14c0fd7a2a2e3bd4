// The 3MF reader and writer: hand-written packages (built with libzip in tests/support/zip_bytes)
// with closed-form figures, every refusal of a malformed model or hostile archive, the write→read
// round trip, and the 3MF Consortium's sample files of ../shared/meshes/3mf when present.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <numbers>
#include <pugixml.hpp>
#include <string>

#include "pgamesh/analysis/analyze.hpp"
#include "pgamesh/io/write_mesh.hpp"
#include "support/file_bytes.hpp"
#include "support/read_helpers.hpp"
#include "support/threemf_package.hpp"

namespace pgamesh {

namespace {

Mesh read_package(const std::string& zip, MeshSource* source = nullptr) {
  return read_mesh_bytes({zip.data(), zip.size()}, "test.3mf", source);
}

InputError package_error(const std::string& zip) {
  try {
    read_package(zip);
  } catch (const InputError& e) {
    return e;
  }
  ADD_FAILURE() << "expected an InputError";
  return InputError("", {}, "");
}

#define EXPECT_3MF_ERROR(zip, text)                           \
  do {                                                        \
    const InputError e_ = package_error(zip);                 \
    EXPECT_TRUE(test::mentions(e_, text)) << e_.what();       \
    EXPECT_TRUE(test::mentions(e_, "test.3mf")) << e_.what(); \
  } while (0)

Analysis analyze_package(const std::string& zip) {
  return analyze_bytes({zip.data(), zip.size()}, "test.3mf");
}

std::string rels_with(const std::string& relationships) {
  return "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<Relationships "
         "xmlns=\"http://schemas.openxmlformats.org/package/2006/relationships\">\n" +
         relationships + "</Relationships>\n";
}

const std::string model_type = "http://schemas.microsoft.com/3dmanufacturing/2013/01/3dmodel";

}  // namespace

TEST(Read3mf, DetectedByZipMagicAndExtension) {
  const std::string zip = test::threemf_package(
      test::threemf_model(test::threemf_box(1, 1, 2, 3), "<item objectid=\"1\"/>"));
  EXPECT_EQ(detect_format({zip.data(), zip.size()}), MeshFormat::threemf);
  EXPECT_EQ(format_for_extension("a/b.3MF"), MeshFormat::threemf);
  EXPECT_EQ(format_from_name("3mf"), MeshFormat::threemf);
  EXPECT_STREQ(format_name(MeshFormat::threemf), "3mf");
}

TEST(Read3mf, BoxHasItsClosedFormFiguresAndDefaultUnit) {
  MeshSource src;
  const std::string zip = test::threemf_package(
      test::threemf_model(test::threemf_box(1, 1, 2, 3, "brick"), "<item objectid=\"1\"/>"));
  const Mesh m = read_package(zip, &src);
  EXPECT_EQ(src.format, MeshFormat::threemf);
  EXPECT_EQ(src.unit, LengthUnit::millimeter);  // no unit attribute: the specification's default
  ASSERT_EQ(src.parts.size(), 1u);
  EXPECT_EQ(src.parts[0].name, "brick");
  EXPECT_EQ(src.parts[0].face_count, 12u);
  EXPECT_EQ(m.vertices.size(), 8u);
  EXPECT_DOUBLE_EQ(test::six_volume(m) / 6, 6.0);
  const Analysis a = analyze_package(zip);
  EXPECT_DOUBLE_EQ(a.mass.volume, 6.0);
  EXPECT_TRUE(a.topology->closed);
  EXPECT_EQ(a.unit, LengthUnit::millimeter);
}

// pugixml's allocation functions are process-wide, and the reader installs its own (huge-page
// arenas during a parse). A program that uses pugixml too, with allocation functions of its own,
// must keep them for its documents: made before a 3MF read and freed after it, or made after it.
std::size_t program_allocations = 0, program_frees = 0;
void* program_allocate(std::size_t bytes) {
  ++program_allocations;
  return std::malloc(bytes);
}
void program_deallocate(void* p) {
  ++program_frees;
  std::free(p);
}

TEST(Read3mf, AProgramsOwnPugixmlAllocatorKeepsItsDocuments) {
  const pugi::allocation_function saved_allocate = pugi::get_memory_allocation_function();
  const pugi::deallocation_function saved_deallocate = pugi::get_memory_deallocation_function();
  pugi::set_memory_management_functions(program_allocate, program_deallocate);
  program_allocations = program_frees = 0;
  {
    pugi::xml_document before;
    ASSERT_TRUE(before.load_string("<parts><part name=\"a\"/><part name=\"b\"/></parts>"));
    const std::string zip = test::threemf_package(
        test::threemf_model(test::threemf_box(1, 1, 2, 3), "<item objectid=\"1\"/>"));
    const std::size_t before_read = program_allocations;
    EXPECT_DOUBLE_EQ(analyze_package(zip).mass.volume, 6.0);
    // The reader's own trees are in its arenas, whatever the program set before.
    EXPECT_EQ(program_allocations, before_read);
    pugi::xml_document after;
    ASSERT_TRUE(after.load_string("<parts><part name=\"c\"/></parts>"));
    EXPECT_STREQ(before.first_child().last_child().attribute("name").value(), "b");
    EXPECT_STREQ(after.first_child().first_child().attribute("name").value(), "c");
  }
  EXPECT_GT(program_allocations, 0u);
  EXPECT_EQ(program_frees, program_allocations);  // every block went back where it came from
  pugi::set_memory_management_functions(saved_allocate, saved_deallocate);
}

TEST(Read3mf, ComponentRotatedAndTranslatedThenItemRotated) {
  // Object 2 holds object 1 (the box 1×2×3) turned +90° about z (row vectors: [x y z]·M =
  // [−y x z]) and moved by (10, 20, 30); the build item turns object 2 by +90° about x
  // ([x y z]·M = [x −z y]). Applied in this order (p·C·T), the box's centre (0.5, 1, 1.5) goes to
  // (9, 20.5, 31.5), then to (9, −31.5, 20.5); its sides along x, y, z become 2, 3, 1.
  const std::string resources =
      test::threemf_box(1, 1, 2, 3) +
      "<object id=\"2\" type=\"model\"><components>"
      "<component objectid=\"1\" transform=\"0 1 0 -1 0 0 0 0 1 10 20 30\"/>"
      "</components></object>\n";
  const std::string zip = test::threemf_package(test::threemf_model(
      resources, "<item objectid=\"2\" transform=\"1 0 0 0 0 1 0 -1 0 0 0 0\"/>"));
  const Analysis a = analyze_package(zip);
  EXPECT_NEAR(a.mass.volume, 6.0, 1e-12);
  EXPECT_NEAR(a.mass.center_of_mass.x, 9.0, 1e-12);
  EXPECT_NEAR(a.mass.center_of_mass.y, -31.5, 1e-12);
  EXPECT_NEAR(a.mass.center_of_mass.z, 20.5, 1e-12);
  // A box of mass m and sides (p, q, r): I_xx = m (q² + r²) / 12, and so on.
  EXPECT_NEAR(a.mass.inertia_com[0][0], 6.0 * (9 + 1) / 12, 1e-10);
  EXPECT_NEAR(a.mass.inertia_com[1][1], 6.0 * (4 + 1) / 12, 1e-10);
  EXPECT_NEAR(a.mass.inertia_com[2][2], 6.0 * (4 + 9) / 12, 1e-10);
  EXPECT_NEAR(a.mass.inertia_com[0][1], 0.0, 1e-10);
  EXPECT_TRUE(a.topology->closed);
  ASSERT_EQ(a.parts.size(), 1u);
  EXPECT_EQ(a.parts[0].part.name, "object 2");
}

TEST(Read3mf, MirroredItemKeepsAPositiveVolumeAndWarns) {
  const std::string zip = test::threemf_package(
      test::threemf_model(test::threemf_box(1, 1, 2, 3),
                          "<item objectid=\"1\" transform=\"-1 0 0 0 1 0 0 0 1 5 0 0\"/>"));
  MeshSource src;
  const Mesh m = read_package(zip, &src);
  EXPECT_NEAR(test::six_volume(m) / 6, 6.0, 1e-12);
  bool warned = false;
  for (const auto& w : src.warnings) warned |= w.find("mirrored") != std::string::npos;
  EXPECT_TRUE(warned);
  const Analysis a = analyze_package(zip);
  EXPECT_NEAR(a.mass.volume, 6.0, 1e-12);
  EXPECT_NEAR(a.mass.center_of_mass.x, 4.5, 1e-12);  // x → 5 − x
  EXPECT_TRUE(a.topology->closed);
  EXPECT_TRUE(a.volume_valid.value_or(false));
}

TEST(Read3mf, UnitIsReadAndFiguresStayInIt) {
  for (const auto& [name, unit] :
       {std::pair{"inch", LengthUnit::inch}, std::pair{"micron", LengthUnit::micron},
        std::pair{"meter", LengthUnit::meter}, std::pair{"foot", LengthUnit::foot},
        std::pair{"centimeter", LengthUnit::centimeter}}) {
    const std::string zip = test::threemf_package(
        test::threemf_model(test::threemf_box(1, 1, 2, 3), "<item objectid=\"1\"/>",
                            std::string("unit=\"") + name + "\""));
    const Analysis a = analyze_package(zip);
    EXPECT_EQ(a.unit, unit) << name;
    EXPECT_DOUBLE_EQ(a.mass.volume, 6.0) << name;  // in the file's unit, never converted
  }
  EXPECT_3MF_ERROR(
      test::threemf_package(test::threemf_model(test::threemf_box(1, 1, 2, 3),
                                                "<item objectid=\"1\"/>", "unit=\"furlong\"")),
      "unknown unit 'furlong'");
}

TEST(Read3mf, SeveralObjectsAreOnePartEachAndAddUp) {
  const std::string zip = test::threemf_package(test::threemf_model(
      test::threemf_box(1, 1, 2, 3, "a") + test::threemf_box(2, 2, 2, 2, "b"),
      "<item objectid=\"1\"/>\n<item objectid=\"2\" transform=\"1 0 0 0 1 0 0 0 1 10 0 0\"/>\n"));
  const Analysis a = analyze_package(zip);
  ASSERT_EQ(a.parts.size(), 2u);
  EXPECT_EQ(a.parts[0].part.name, "a");
  EXPECT_EQ(a.parts[1].part.name, "b");
  EXPECT_EQ(a.parts[1].part.first_face, 12u);
  EXPECT_DOUBLE_EQ(a.parts[0].mass.volume, 6.0);
  EXPECT_DOUBLE_EQ(a.parts[1].mass.volume, 8.0);
  EXPECT_DOUBLE_EQ(a.mass.volume, 14.0);
  EXPECT_NEAR(a.parts[1].mass.center_of_mass.x, 11.0, 1e-12);
  // The whole's centre of mass is the volume-weighted mean of the parts'.
  EXPECT_NEAR(a.mass.center_of_mass.x, (6 * 0.5 + 8 * 11.0) / 14, 1e-12);
  EXPECT_TRUE(a.parts[0].topology->closed);
  EXPECT_EQ(a.topology->components, 2u);
}

TEST(Read3mf, IgnoredExtensionsWarnOncePerKind) {
  const std::string resources =
      "<m:basematerials id=\"5\" "
      "xmlns:m=\"http://schemas.microsoft.com/3dmanufacturing/material/2015/02\">"
      "<m:base name=\"red\" displaycolor=\"#FF0000\"/></m:basematerials>\n"
      "<m:colorgroup id=\"6\" xmlns:m=\"x\"><m:color color=\"#00FF00\"/></m:colorgroup>\n" +
      test::threemf_box(1, 1, 2, 3);
  std::string model = test::threemf_model(resources, "<item objectid=\"1\"/>");
  // A beam lattice inside the mesh.
  model.replace(model.find("</mesh>"), 0,
                "<b:beamlattice xmlns:b=\"y\"><b:beams/></b:beamlattice>");
  MeshSource src;
  read_package(test::threemf_package(model), &src);
  auto count = [&](const char* what) {
    int n = 0;
    for (const auto& w : src.warnings) n += w.find(what) != std::string::npos;
    return n;
  };
  EXPECT_EQ(count("materials"), 1);
  EXPECT_EQ(count("colours"), 1);
  EXPECT_EQ(count("beam lattice"), 1);
  EXPECT_EQ(count("no volume"), 1);
}

TEST(Read3mf, MalformedModelsAreRefusedNamingTheProblem) {
  const std::string box = test::threemf_box(1, 1, 2, 3);
  const std::string item = "<item objectid=\"1\"/>";
  auto with = [&](std::string text, const std::string& from, const std::string& to) {
    text.replace(text.find(from), from.size(), to);
    return test::threemf_package(test::threemf_model(text, item));
  };
  EXPECT_3MF_ERROR(with(box, "v2=\"2\"", "v2=\"0\""), "repeated vertex index");
  EXPECT_3MF_ERROR(with(box, "v2=\"2\"", "v2=\"8\""), "out of range");
  EXPECT_3MF_ERROR(with(box, "v2=\"2\"", "v2=\"-1\""), "malformed index");
  EXPECT_3MF_ERROR(with(box, "x=\"1.000000\"", "x=\"1.0.0\""), "malformed number");
  EXPECT_3MF_ERROR(with(box, "x=\"1.000000\"", "x=\"\""), "malformed number");
  EXPECT_3MF_ERROR(with(box, "x=\"1.000000\"", "x=\"nan\""), "non-finite");
  EXPECT_3MF_ERROR(with(box, "x=\"1.000000\"", "x=\"inf\""), "non-finite");
  EXPECT_3MF_ERROR(with(box, "x=\"1.000000\"", "x=\"1e999\""), "out of double range");
  EXPECT_3MF_ERROR(with(box, "<vertex x=\"1.000000\"", "<vertex"), "missing coordinate");
  EXPECT_3MF_ERROR(
      test::threemf_package(test::threemf_model(box + test::threemf_box(1, 1, 1, 1), item)),
      "duplicate resource id 1");
  EXPECT_3MF_ERROR(test::threemf_package(test::threemf_model(box, "<item objectid=\"7\"/>")),
                   "objectid 7 names no object");
  EXPECT_3MF_ERROR(test::threemf_package(test::threemf_model(
                       "<object id=\"2\"><components><component objectid=\"9\"/></components>"
                       "</object>",
                       "<item objectid=\"2\"/>")),
                   "objectid 9 names no object");
  EXPECT_3MF_ERROR(test::threemf_package(test::threemf_model(
                       "<object id=\"2\"><components><component objectid=\"3\"/></components>"
                       "</object><object id=\"3\"><components><component objectid=\"2\"/>"
                       "</components></object>",
                       "<item objectid=\"2\"/>")),
                   "component cycle");
  EXPECT_3MF_ERROR(
      test::threemf_package(test::threemf_model(box, "<item objectid=\"1\" transform=\"1 0 0\"/>")),
      "12 numbers");
  EXPECT_3MF_ERROR(test::threemf_package(test::threemf_model(
                       box, "<item objectid=\"1\" transform=\"1 0 0 0 1 0 0 0 1 0 0 nan\"/>")),
                   "non-finite");
  EXPECT_3MF_ERROR(test::threemf_package("<model><resources>"), "malformed XML");
}

TEST(Read3mf, ErrorsGiveTheLineAndColumnInTheModelPart) {
  // Line 1 the declaration, 2 <model>, 3 <resources>, 4 <object>, 5 <mesh>, 6 <vertices>, 7–14
  // the vertices, 15 </vertices>, 16 <triangles>, 17 the first triangle.
  std::string box = test::threemf_box(1, 1, 2, 3);
  box.replace(box.find("v3=\"1\""), 6, "v3=\"9\"");
  const InputError e =
      package_error(test::threemf_package(test::threemf_model(box, "<item objectid=\"1\"/>")));
  EXPECT_TRUE(e.where().has_line) << e.what();
  EXPECT_EQ(e.where().line, 17u) << e.what();
  EXPECT_EQ(e.where().column, 29u) << e.what();  // the value of v3: <triangle v1="0" v2="2" v3="
  EXPECT_TRUE(test::mentions(e, "/3D/3dmodel.model")) << e.what();
  EXPECT_TRUE(test::mentions(e, "<triangle v3>")) << e.what();
}

TEST(Read3mf, PackageStructureErrors) {
  const std::string model =
      test::threemf_model(test::threemf_box(1, 1, 2, 3), "<item objectid=\"1\"/>");
  auto package = [&](const std::string& rels) {
    return test::zip_bytes({{"_rels/.rels", rels_with(rels)}, {"3D/3dmodel.model", model}});
  };
  EXPECT_3MF_ERROR(package(""), "missing model part");
  EXPECT_3MF_ERROR(
      package("<Relationship Target=\"/3D/other.model\" Id=\"r\" Type=\"" + model_type + "\"/>"),
      "missing model part");
  EXPECT_3MF_ERROR(package("<Relationship Target=\"http://example.com/m.model\" Id=\"r\" "
                           "TargetMode=\"External\" Type=\"" +
                           model_type + "\"/>"),
                   "External");
  EXPECT_3MF_ERROR(
      package("<Relationship Target=\"/3D/3dmodel.model\" Id=\"r\" Type=\"" + model_type +
              "\"/>\n<Relationship Target=\"/3D/3dmodel.model\" Id=\"s\" Type=\"" + model_type +
              "\"/>"),
      "more than one 3D model relationship");
  EXPECT_3MF_ERROR(test::zip_bytes({{"3D/3dmodel.model", model}}), "no _rels/.rels");
  // A relative target is relative to the package root; it reads.
  const std::string relative =
      package("<Relationship Target=\"3D/3dmodel.model\" Id=\"r\" Type=\"" + model_type + "\"/>");
  EXPECT_EQ(read_package(relative).face_count(), 12u);
}

TEST(Read3mf, HostileArchivesAreRefused) {
  const std::string model =
      test::threemf_model(test::threemf_box(1, 1, 2, 3), "<item objectid=\"1\"/>");
  const std::string good = test::threemf_package(model);
  EXPECT_EQ(read_package(good).face_count(), 12u);

  // Truncated: the central directory is at the end.
  EXPECT_3MF_ERROR(good.substr(0, good.size() / 2), "not a readable zip archive");
  EXPECT_3MF_ERROR(good.substr(0, good.size() - 5), "not a readable zip archive");

  // Path traversal in an entry name, even one never read.
  std::string traversal =
      test::zip_bytes({{"_rels/.rels", rels_with("")}, {"3D/../../evil.model", model}});
  EXPECT_3MF_ERROR(traversal, "path traversal");
  EXPECT_3MF_ERROR(test::zip_bytes({{"/etc/passwd", "x"}}), "path traversal");

  // Encrypted (general-purpose flag bit 0) and an unsupported method (12, bzip2).
  std::string encrypted = good;
  ASSERT_TRUE(test::set_zip_flags(encrypted, "3D/3dmodel.model", 1));
  EXPECT_3MF_ERROR(encrypted, "encrypted");
  std::string bzip2 = good;
  ASSERT_TRUE(test::set_zip_method(bzip2, "3D/3dmodel.model", 12));
  EXPECT_3MF_ERROR(bzip2, "compression method 12 not supported");

  // A zip bomb: a model padded with 64 MiB of blanks (valid XML) deflates to about 64 KiB; its
  // declared size is beyond the budget (256 × the archive + 32 MiB).
  std::string padded = model + std::string(std::size_t{64} << 20, ' ');
  const std::string bomb = test::threemf_package(padded);
  ASSERT_LT(bomb.size(), std::size_t{200} << 10);
  EXPECT_3MF_ERROR(bomb, "beyond the limit");
  // The same bomb whose headers declare 1000 bytes: caught while inflating, after 1001 bytes.
  std::string liar = bomb;
  ASSERT_TRUE(test::set_zip_size(liar, "3D/3dmodel.model", 1000));
  EXPECT_3MF_ERROR(liar, "beyond its declared size");
  // Declared larger than it is: the inflated part comes up short.
  std::string short_part = good;
  ASSERT_TRUE(test::set_zip_size(short_part, "3D/3dmodel.model",
                                 static_cast<std::uint32_t>(model.size() + 10)));
  EXPECT_3MF_ERROR(short_part, "3D/3dmodel.model");
}

TEST(Read3mf, InstancingBombIsRefused) {
  // Ten levels of ten components each: 10^10 boxes from a file of a few KiB.
  std::string resources = test::threemf_box(1, 1, 1, 1);
  for (int level = 2; level <= 11; ++level) {
    resources += "<object id=\"" + std::to_string(level) + "\"><components>";
    for (int k = 0; k < 10; ++k)
      resources += "<component objectid=\"" + std::to_string(level - 1) + "\"/>";
    resources += "</components></object>\n";
  }
  EXPECT_3MF_ERROR(test::threemf_package(test::threemf_model(resources, "<item objectid=\"11\"/>")),
                   "the build expands to");
}

TEST(Write3mf, RoundTripIsBitExact) {
  Mesh m;
  m.vertices = {{0.1, -0.0, 1e-300},
                {1.0 / 3, 2.5e17, -7.25},
                {std::nextafter(1.0, 2.0), 4, 5},
                {-1e308, 3.0, 0.3}};
  m.add_face({0, 1, 2});
  m.add_face({0, 2, 3});
  m.add_face({1, 3, 2});
  for (LengthUnit unit : {LengthUnit::unspecified, LengthUnit::inch, LengthUnit::micron}) {
    WriteOptions o;
    o.unit = unit;
    const std::string bytes = write_mesh_bytes(m, MeshFormat::threemf, o);
    MeshSource src;
    const Mesh back = read_mesh_bytes({bytes.data(), bytes.size()}, "rt.3mf", &src);
    EXPECT_EQ(src.unit, unit == LengthUnit::unspecified ? LengthUnit::millimeter : unit);
    ASSERT_EQ(back.vertices.size(), m.vertices.size());
    EXPECT_EQ(
        std::memcmp(back.vertices.data(), m.vertices.data(), m.vertices.size() * sizeof(Vec3d)), 0);
    EXPECT_EQ(back.corners, m.corners);
    EXPECT_EQ(back.face_offsets, m.face_offsets);
  }
  Mesh repeated = m;
  repeated.add_face({0, 0, 1});
  EXPECT_THROW(write_mesh_bytes(repeated, MeshFormat::threemf), std::invalid_argument);
}

namespace {

// The 3MF Consortium's samples: read, written as OBJ and read back with the same figures.
Analysis sample(const std::string& path) {
  const Analysis a = analyze_file(path);
  MeshSource src;
  const Mesh m = read_mesh(path, &src);
  const std::string obj = write_mesh_bytes(m, MeshFormat::obj);
  const Mesh back = read_mesh_bytes({obj.data(), obj.size()}, "back.obj");
  EXPECT_EQ(back.corners, m.corners);
  EXPECT_EQ(std::memcmp(back.vertices.data(), m.vertices.data(), m.vertices.size() * sizeof(Vec3d)),
            0);
  EXPECT_EQ(src.unit, LengthUnit::millimeter);
  EXPECT_EQ(a.mass.volume, analyze_mesh(back, MeshSource{}).mass.volume);
  return a;
}

struct Extent {
  Vec3d lo{1e300, 1e300, 1e300}, hi{-1e300, -1e300, -1e300};
};

Extent extent_of(const std::string& path) {
  Extent e;
  for (const Vec3d& v : read_mesh(path).vertices)
    for (int k = 0; k < 3; ++k) {
      e.lo[k] = std::min(e.lo[k], v[k]);
      e.hi[k] = std::max(e.hi[k], v[k]);
    }
  return e;
}

}  // namespace

TEST(Read3mfSamples, BoxVolumeIsItsExtentProduct) {
  SHARED_MESH_EXTRA(path, "3mf/box.3mf");
  const Analysis a = sample(path);
  const Extent e = extent_of(path);
  EXPECT_DOUBLE_EQ(a.mass.volume, (e.hi.x - e.lo.x) * (e.hi.y - e.lo.y) * (e.hi.z - e.lo.z));
  EXPECT_TRUE(a.topology->closed);
}

TEST(Read3mfSamples, SphereCylinderTorusNearTheirClosedForms) {
  SHARED_MESH_EXTRA(sphere, "3mf/sphere.3mf");
  SHARED_MESH_EXTRA(cylinder, "3mf/cylinder.3mf");
  SHARED_MESH_EXTRA(torus, "3mf/torus.3mf");
  const double pi = std::numbers::pi;
  {
    const Analysis a = sample(sphere);
    const Extent e = extent_of(sphere);
    const double r = (e.hi.x - e.lo.x) / 2;
    const double exact = 4 * pi * r * r * r / 3;
    EXPECT_LT(a.mass.volume, exact);  // an inscribed polyhedron
    EXPECT_NEAR(a.mass.volume / exact, 1.0, 0.03);
    // Its tessellation is not quite symmetric: the centre of mass is off the box's by 2.5e-6 r.
    EXPECT_NEAR(a.mass.center_of_mass.x, (e.hi.x + e.lo.x) / 2, 1e-5 * r);
  }
  {
    const Analysis a = sample(cylinder);
    const Extent e = extent_of(cylinder);
    const Vec3d d = e.hi - e.lo;
    // Two equal extents are the diameter, the third the height.
    const double r = (d.x == d.y ? d.x : d.x == d.z ? d.x : d.y) / 2;
    const double h = d.x == d.y ? d.z : d.x == d.z ? d.y : d.x;
    const double exact = pi * r * r * h;
    EXPECT_LT(a.mass.volume, exact * (1 + 1e-12));
    EXPECT_NEAR(a.mass.volume / exact, 1.0, 0.03);
  }
  {
    const Analysis a = sample(torus);
    const Extent e = extent_of(torus);
    const Vec3d d = e.hi - e.lo;
    const double tube = std::min({d.x, d.y, d.z}) / 2;
    const double outer = std::max({d.x, d.y, d.z}) / 2;
    const double exact = 2 * pi * pi * (outer - tube) * tube * tube;
    EXPECT_NEAR(a.mass.volume / exact, 1.0, 0.05);
    EXPECT_TRUE(a.topology->closed);
  }
}

TEST(Read3mfSamples, MultipleCylindersAreSixEqualItems) {
  SHARED_MESH_EXTRA(path, "3mf/multiple_cylinders.3mf");
  const Analysis a = sample(path);
  ASSERT_EQ(a.parts.size(), 6u);
  double sum = 0;
  for (const PartAnalysis& p : a.parts) {
    EXPECT_NEAR(p.mass.volume, a.parts[0].mass.volume, 1e-9 * a.parts[0].mass.volume);
    EXPECT_EQ(p.part.name, "Cylinder");
    sum += p.mass.volume;
  }
  EXPECT_NEAR(a.mass.volume, sum, 1e-9 * sum);
  // The items translate the one cylinder by these offsets, in the file's order.
  const double offsets[6][2] = {{0, 0},       {21, 0},       {42, 0},
                                {0, 20.7964}, {21, 20.7964}, {42, 20.7964}};
  for (int i = 1; i < 6; ++i) {
    const Vec3d d = a.parts[i].mass.center_of_mass - a.parts[0].mass.center_of_mass;
    EXPECT_NEAR(d.x, offsets[i][0], 1e-9) << i;
    EXPECT_NEAR(d.y, offsets[i][1], 1e-9) << i;
    EXPECT_NEAR(d.z, 0, 1e-9) << i;
  }
}

TEST(Read3mfSamples, CubeGearsAreSeventeenClosedItems) {
  SHARED_MESH_EXTRA(path, "3mf/cube_gears.3mf");
  const Analysis a = sample(path);
  ASSERT_EQ(a.parts.size(), 17u);
  double sum = 0;
  for (const PartAnalysis& p : a.parts) {
    EXPECT_GT(p.mass.volume, 0);
    sum += p.mass.volume;
  }
  EXPECT_NEAR(a.mass.volume, sum, 1e-9 * sum);
}

}  // namespace pgamesh
