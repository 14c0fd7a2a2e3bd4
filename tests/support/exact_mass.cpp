#include "exact_mass.hpp"

#ifdef PGAMESH_HAVE_GMP

namespace pgamesh::test {

namespace {

using Q3 = std::array<mpq_class, 3>;

Q3 exact(Vec3d v) {
  return {mpq_class(v.x), mpq_class(v.y), mpq_class(v.z)};
}

mpq_class det(const Q3& a, const Q3& b, const Q3& c) {
  return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
         a[2] * (b[0] * c[1] - b[1] * c[0]);
}

// The signed tetrahedron (0, a, b, c): volume D/6, ∫ r = D/24 (a + b + c),
// ∫ r_i r_j = D/120 (Σ_k a_i a_j + … + s_i s_j), s = a + b + c (the moments of a simplex).
void add_tetrahedron(ExactMass& m, const Q3& a, const Q3& b, const Q3& c) {
  const mpq_class d = det(a, b, c);
  m.volume += d / 6;
  Q3 s;
  for (int i = 0; i < 3; ++i) {
    s[i] = a[i] + b[i] + c[i];
    m.first[i] += d * s[i] / 24;
  }
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      m.second[3 * i + j] += d * (a[i] * a[j] + b[i] * b[j] + c[i] * c[j] + s[i] * s[j]) / 120;
}

}  // namespace

ExactMass exact_mass(const Mesh& mesh) {
  ExactMass m;
  for (std::size_t f = 0; f < mesh.face_count(); ++f) {
    const std::uint32_t* c = mesh.face(f);
    const Q3 v0 = exact(mesh.vertices[c[0]]);
    for (std::size_t k = 1; k + 1 < mesh.face_size(f); ++k)
      add_tetrahedron(m, v0, exact(mesh.vertices[c[k]]), exact(mesh.vertices[c[k + 1]]));
  }
  return m;
}

ExactSummary exact_summary(const Mesh& mesh) {
  const ExactMass m = exact_mass(mesh);
  ExactSummary s;
  s.volume = m.volume.get_d();
  Q3 c;
  for (int i = 0; i < 3; ++i) {
    c[i] = m.first[i] / m.volume;
    s.center_of_mass[i] = c[i].get_d();
  }
  // Central second moments M_c = M − V c cᵀ, then I = tr(M_c) 1 − M_c.
  std::array<mpq_class, 9> mc;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) mc[3 * i + j] = m.second[3 * i + j] - m.volume * c[i] * c[j];
  const mpq_class trace = mc[0] + mc[4] + mc[8];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      const mpq_class v = (i == j ? trace : mpq_class(0)) - mc[3 * i + j];
      s.inertia_com[i][j] = v.get_d();
    }
  return s;
}

}  // namespace pgamesh::test

#endif
