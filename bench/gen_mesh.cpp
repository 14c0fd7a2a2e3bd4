// Benchmark input generator: a closed, outward torus of about N triangles written as binary STL,
// ASCII STL, OBJ, ASCII PLY, binary PLY (little-endian float32 vertices, uchar/int faces: 19 B per
// triangle), OFF or 3MF (pgamesh's writer, millimeter). Coordinates are rounded to float32 first,
// so every format holds the same numbers and every tool reads the same solid.
//   pgamesh_gen_mesh TRIANGLES FORMAT OUT  FORMAT: stl|stl-ascii|obj|ply|ply-bin|off|3mf
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <numbers>
#include <string>
#include <vector>

#include "pgamesh/io/write_mesh.hpp"

namespace {

struct Torus {
  int u = 0, v = 0;              // segments around the big circle and the tube
  std::vector<float> xyz;        // vertex coordinates
  std::vector<std::uint32_t> t;  // triangles, three indices each

  Torus(long long triangles, double big_r, double small_r) {
    // 2 u v triangles with u ≈ (R / r) v keeps the quads near square.
    const double ratio = big_r / small_r;
    v = std::max(3, static_cast<int>(std::lround(std::sqrt(triangles / (2.0 * ratio)))));
    u = std::max(3, static_cast<int>(std::lround(triangles / (2.0 * v))));
    const double pi = std::numbers::pi;
    for (int i = 0; i < u; ++i)
      for (int j = 0; j < v; ++j) {
        const double a = 2 * pi * i / u, b = 2 * pi * j / v;
        const double rr = big_r + small_r * std::cos(b);
        xyz.push_back(static_cast<float>(rr * std::cos(a)));
        xyz.push_back(static_cast<float>(rr * std::sin(a)));
        xyz.push_back(static_cast<float>(small_r * std::sin(b)));
      }
    const auto id = [&](int i, int j) { return static_cast<std::uint32_t>((i % u) * v + (j % v)); };
    for (int i = 0; i < u; ++i)
      for (int j = 0; j < v; ++j) {
        // Outward: (i, j) → (i+1, j) → (i+1, j+1) runs counter-clockwise seen from outside.
        t.insert(t.end(), {id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        t.insert(t.end(), {id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      }
  }
  std::size_t vertices() const { return xyz.size() / 3; }
  std::size_t triangles() const { return t.size() / 3; }
};

int fail(const char* what) {
  std::fprintf(stderr, "pgamesh_gen_mesh: %s\n", what);
  return 1;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4)
    return fail("usage: pgamesh_gen_mesh TRIANGLES stl|stl-ascii|obj|ply|ply-bin|off|3mf OUT");
  const long long n = std::atoll(argv[1]);
  if (n < 8 || n > 200000000) return fail("TRIANGLES must be from 8 to 2e8");
  const std::string format = argv[2];
  std::FILE* out = std::fopen(argv[3], "wb");
  if (!out) return fail("cannot open the output file");
  static char buffer[1 << 20];
  std::setvbuf(out, buffer, _IOFBF, sizeof buffer);
  const Torus m(n, 3.0, 1.0);
  const auto p = [&](std::uint32_t k) { return &m.xyz[3 * k]; };
  if (format == "stl") {
    char header[80] = "pgamesh_gen_mesh torus";
    std::fwrite(header, 1, 80, out);
    const auto count = static_cast<std::uint32_t>(m.triangles());
    std::fwrite(&count, 4, 1, out);
    for (std::size_t f = 0; f < m.triangles(); ++f) {
      char rec[50] = {};
      for (int k = 0; k < 3; ++k) std::memcpy(rec + 12 + 12 * k, p(m.t[3 * f + k]), 12);
      std::fwrite(rec, 1, 50, out);
    }
  } else if (format == "stl-ascii") {
    std::fprintf(out, "solid torus\n");
    for (std::size_t f = 0; f < m.triangles(); ++f) {
      std::fprintf(out, "facet normal 0 0 0\n outer loop\n");
      for (int k = 0; k < 3; ++k) {
        const float* q = p(m.t[3 * f + k]);
        std::fprintf(out, "  vertex %.9g %.9g %.9g\n", q[0], q[1], q[2]);
      }
      std::fprintf(out, " endloop\nendfacet\n");
    }
    std::fprintf(out, "endsolid torus\n");
  } else if (format == "ply-bin") {
    if constexpr (std::endian::native != std::endian::little)
      return fail("ply-bin is written on little-endian hosts only");
    std::fprintf(out,
                 "ply\nformat binary_little_endian 1.0\nelement vertex %zu\nproperty float "
                 "x\nproperty float y\nproperty float z\nelement face %zu\nproperty list uchar "
                 "int vertex_indices\nend_header\n",
                 m.vertices(), m.triangles());
    std::fwrite(m.xyz.data(), sizeof(float), m.xyz.size(), out);
    for (std::size_t f = 0; f < m.triangles(); ++f) {
      char rec[13] = {3};
      std::memcpy(rec + 1, &m.t[3 * f], 12);
      std::fwrite(rec, 1, 13, out);
    }
  } else if (format == "obj" || format == "ply" || format == "off") {
    if (format == "ply")
      std::fprintf(out,
                   "ply\nformat ascii 1.0\nelement vertex %zu\nproperty float x\nproperty float "
                   "y\nproperty float z\nelement face %zu\nproperty list uchar int "
                   "vertex_indices\nend_header\n",
                   m.vertices(), m.triangles());
    if (format == "off") std::fprintf(out, "OFF\n%zu %zu 0\n", m.vertices(), m.triangles());
    const char* vtag = format == "obj" ? "v " : "";
    for (std::size_t k = 0; k < m.vertices(); ++k)
      std::fprintf(out, "%s%.9g %.9g %.9g\n", vtag, m.xyz[3 * k], m.xyz[3 * k + 1],
                   m.xyz[3 * k + 2]);
    for (std::size_t f = 0; f < m.triangles(); ++f) {
      if (format == "obj")
        std::fprintf(out, "f %u %u %u\n", m.t[3 * f] + 1, m.t[3 * f + 1] + 1, m.t[3 * f + 2] + 1);
      else
        std::fprintf(out, "3 %u %u %u\n", m.t[3 * f], m.t[3 * f + 1], m.t[3 * f + 2]);
    }
  } else if (format == "3mf") {
    pgamesh::Mesh mesh;
    for (std::size_t k = 0; k < m.vertices(); ++k)
      mesh.vertices.push_back({p(k)[0], p(k)[1], p(k)[2]});
    for (std::size_t f = 0; f < m.triangles(); ++f)
      mesh.add_face({m.t[3 * f], m.t[3 * f + 1], m.t[3 * f + 2]});
    pgamesh::WriteOptions o;
    o.unit = pgamesh::LengthUnit::millimeter;
    const std::string bytes = pgamesh::write_mesh_bytes(mesh, pgamesh::MeshFormat::threemf, o);
    std::fwrite(bytes.data(), 1, bytes.size(), out);
  } else {
    std::fclose(out);
    return fail("unknown format (stl, stl-ascii, obj, ply, ply-bin, off, 3mf)");
  }
  if (std::fclose(out) != 0) return fail("write failed");
  std::printf("%zu triangles, %zu vertices\n", m.triangles(), m.vertices());
  return 0;
}
