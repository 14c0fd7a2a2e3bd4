// The mesh container: plain arrays, libigl style. Faces are polygons of any size stored as one flat
// list of corner indices with offsets (CSR), so triangles, quads and n-gons share one layout and
// n-gons are never triangulated behind the user's back (paper §4c measures them from their edges).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "pgamesh/core/units.hpp"
#include "pgamesh/core/vec3.hpp"

namespace pgamesh {

enum class MeshFormat {
  unknown,
  stl_ascii,
  stl_binary,
  obj,
  ply_ascii,
  ply_binary_le,
  ply_binary_be,
  off,
  gltf,    // glTF 2.0 JSON (.gltf)
  glb,     // glTF 2.0 binary container (.glb)
  slp,     // Pro/ENGINEER render file: ASCII STL with colours and vertex normals
  threemf  // 3MF package (.3mf)
};

struct Mesh {
  std::vector<Vec3d> vertices;
  std::vector<std::uint32_t> corners;  // vertex indices of every face, face after face
  std::vector<std::uint32_t> face_offsets{
      0};  // face f is corners[face_offsets[f] .. face_offsets[f+1])

  std::size_t face_count() const { return face_offsets.size() - 1; }
  std::size_t face_size(std::size_t f) const { return face_offsets[f + 1] - face_offsets[f]; }
  const std::uint32_t* face(std::size_t f) const { return corners.data() + face_offsets[f]; }
  void add_face(std::initializer_list<std::uint32_t> idx) {
    corners.insert(corners.end(), idx.begin(), idx.end());
    face_offsets.push_back(static_cast<std::uint32_t>(corners.size()));
  }
};

// A named part of a file that holds several (a 3MF build item, a glTF node's mesh): its faces are
// faces [first_face, first_face + face_count) of the mesh read, already placed by the file's
// transforms.
struct MeshPart {
  std::string name;
  std::uint32_t first_face = 0;
  std::uint32_t face_count = 0;
};

// What a reader learned about the file besides the geometry.
struct MeshSource {
  std::string path;
  MeshFormat format = MeshFormat::unknown;
  bool single_precision = false;  // coordinates were float32 (binary STL, float PLY, glTF)
  std::uint64_t groups = 0;       // OBJ g/o statements (ignored, counted)
  LengthUnit unit = LengthUnit::unspecified;  // the file's own unit, if it states one
  std::vector<MeshPart> parts;                // empty for formats of one object
  std::vector<std::string> warnings;
};

}  // namespace pgamesh
