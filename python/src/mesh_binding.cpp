// pgamesh.Mesh, pgamesh.load and pgamesh.analyze_file: the front door (analysis/analyze.hpp) for
// Python, in trimesh's vocabulary (docs/python.md). Every figure is the library's; the dicts of
// analyze_file, Mesh.props and Mesh.check are the CLI's JSON documents (apps/common) parsed.
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string>

#include "bindings.hpp"
#include "check_json.hpp"
#include "json_text.hpp"
#include "pgamesh/analysis/analyze.hpp"
#include "pgamesh/io/mesh_format.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/mesh/topology/topology.hpp"
#include "props_report.hpp"

namespace pgamesh::python {

namespace {

// A mesh as Python holds it: the arrays, what the reader said of the source and the weld tolerance
// of the topology, with the front door's analysis (density 1, topology on) made on first use.
struct PythonMesh {
  Mesh mesh;
  MeshSource source;
  double weld_tolerance = 0;
  std::optional<Analysis> analysis;
  std::mutex analysis_mutex;

  const Analysis& analyzed() {
    {
      py::gil_scoped_release release;
      const std::lock_guard lock(analysis_mutex);
      if (!analysis) {
        AnalysisOptions options;
        options.topology_options.weld_tolerance = weld_tolerance;
        analysis = analyze_mesh(mesh, source, options);
      }
    }
    return *analysis;
  }
  const TopologyReport& topology() { return *analyzed().topology; }
};

double weld_tolerance_from(const std::optional<double>& tolerance) {
  const double t = tolerance.value_or(0.0);
  if (!(t >= 0) || !std::isfinite(t))
    throw py::value_error("weld_tolerance must be finite and not negative");
  return t;
}

MeshFormat format_from(const std::optional<std::string>& name) {
  if (!name) return MeshFormat::unknown;
  const MeshFormat f = format_from_name(*name);
  if (f == MeshFormat::unknown && *name != "auto")
    throw py::value_error("unknown mesh format '" + *name + "'");
  return f;
}

std::unique_ptr<PythonMesh> load(const py::object& source, std::optional<double> weld_tolerance,
                                 std::optional<std::string> format) {
  auto m = std::make_unique<PythonMesh>();
  m->weld_tolerance = weld_tolerance_from(weld_tolerance);
  const MeshFormat f = format_from(format);
  if (py::isinstance<py::bytes>(source) || py::isinstance<py::bytearray>(source) ||
      py::isinstance<py::memoryview>(source)) {
    // The buffer is read in place while the GIL is released: a bytes object cannot change, and
    // a bytearray or memoryview is held by the caller's reference for the duration of the call.
    const py::buffer_info info = py::reinterpret_borrow<py::buffer>(source).request();
    const std::span<const char> bytes(static_cast<const char*>(info.ptr),
                                      static_cast<std::size_t>(info.size * info.itemsize));
    py::gil_scoped_release release;
    m->mesh = read_mesh_bytes(bytes, "<bytes>", &m->source, f);
  } else {
    const std::string path = py::str(py::module_::import("os").attr("fspath")(source));
    py::gil_scoped_release release;
    m->mesh = read_mesh(path, &m->source, f);
  }
  return m;
}

// Rows of an (n, 3) float64 array, each finite.
std::vector<Vec3d> vertices_from(const py::handle& value) {
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(value);
  if (!a) throw py::value_error("vertices must be an (n, 3) array of numbers");
  if (a.ndim() != 2 || a.shape(1) != 3)
    throw py::value_error("vertices must have shape (n, 3), not " +
                          std::string(py::str(py::cast(a.request().shape))));
  const auto r = a.unchecked<2>();
  std::vector<Vec3d> out(static_cast<std::size_t>(a.shape(0)));
  for (py::ssize_t i = 0; i < a.shape(0); ++i) {
    out[i] = {r(i, 0), r(i, 1), r(i, 2)};
    if (!is_finite(out[i]))
      throw py::value_error("vertices row " + std::to_string(i) + " is not finite");
  }
  return out;
}

// One face's corners, each an index of an existing vertex.
void add_face(Mesh& mesh, const py::handle& row, std::size_t f) {
  const auto a = py::array::ensure(row);
  if (!a || a.ndim() != 1 || (a.dtype().kind() != 'i' && a.dtype().kind() != 'u'))
    throw py::value_error("faces row " + std::to_string(f) +
                          " must be a sequence of integer vertex indices");
  if (a.shape(0) < 3)
    throw py::value_error("faces row " + std::to_string(f) + " has fewer than three corners");
  const auto idx = a.cast<py::array_t<long long, py::array::forcecast>>();
  const auto r = idx.unchecked<1>();
  for (py::ssize_t k = 0; k < idx.shape(0); ++k) {
    if (r(k) < 0 || static_cast<unsigned long long>(r(k)) >= mesh.vertices.size())
      throw py::value_error("faces row " + std::to_string(f) + ": vertex index " +
                            std::to_string(r(k)) + " is out of range (" +
                            std::to_string(mesh.vertices.size()) + " vertices)");
    mesh.corners.push_back(static_cast<std::uint32_t>(r(k)));
  }
  mesh.face_offsets.push_back(static_cast<std::uint32_t>(mesh.corners.size()));
}

std::unique_ptr<PythonMesh> from_arrays(const py::object& vertices, const py::object& faces,
                                        std::optional<double> weld_tolerance) {
  auto m = std::make_unique<PythonMesh>();
  m->weld_tolerance = weld_tolerance_from(weld_tolerance);
  m->mesh.vertices = vertices_from(vertices);
  if (m->mesh.vertices.size() > std::numeric_limits<std::uint32_t>::max())
    throw py::value_error("too many vertices for 32-bit indices");
  const auto rect = py::array::ensure(faces);
  if (rect && rect.ndim() == 2 && (rect.dtype().kind() == 'i' || rect.dtype().kind() == 'u')) {
    // An (m, k) integer array: m faces of k corners, validated row by row.
    if (rect.shape(1) < 3) throw py::value_error("faces must have at least three columns");
    const auto idx = rect.cast<py::array_t<long long, py::array::c_style | py::array::forcecast>>();
    const auto r = idx.unchecked<2>();
    const auto n = static_cast<long long>(m->mesh.vertices.size());
    m->mesh.corners.reserve(static_cast<std::size_t>(idx.size()));
    m->mesh.face_offsets.reserve(static_cast<std::size_t>(idx.shape(0)) + 1);
    for (py::ssize_t f = 0; f < idx.shape(0); ++f) {
      for (py::ssize_t k = 0; k < idx.shape(1); ++k) {
        if (r(f, k) < 0 || r(f, k) >= n)
          throw py::value_error("faces row " + std::to_string(f) + ": vertex index " +
                                std::to_string(r(f, k)) + " is out of range (" + std::to_string(n) +
                                " vertices)");
        m->mesh.corners.push_back(static_cast<std::uint32_t>(r(f, k)));
      }
      m->mesh.face_offsets.push_back(static_cast<std::uint32_t>(m->mesh.corners.size()));
    }
  } else if (rect && rect.ndim() == 2) {
    throw py::value_error("faces must hold integer vertex indices, not " +
                          std::string(py::str(rect.dtype())));
  } else {
    std::size_t f = 0;  // a sequence of polygons of any sizes
    for (const py::handle row : py::iter(faces)) add_face(m->mesh, row, f++);
  }
  m->source.path = "<arrays>";
  return m;
}

// A read-only numpy view of `count` × `columns` values at `data`, kept alive by `owner`.
template <class T>
py::array view(const T* data, std::size_t count, std::size_t columns, const py::handle& owner) {
  std::vector<py::ssize_t> shape{static_cast<py::ssize_t>(count)};
  std::vector<py::ssize_t> strides{static_cast<py::ssize_t>(columns * sizeof(T))};
  if (columns > 1) {
    shape.push_back(static_cast<py::ssize_t>(columns));
    strides.push_back(sizeof(T));
  }
  py::array a(py::dtype::of<T>(), shape, strides, data, owner);
  py::detail::array_proxy(a.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return a;
}

bool all_triangles(const Mesh& mesh) {
  for (std::size_t f = 0; f < mesh.face_count(); ++f)
    if (mesh.face_size(f) != 3) return false;
  return true;
}

MassOptions mass_options(std::optional<double> density, std::optional<double> mass) {
  if (density && mass) throw py::value_error("give density or mass, not both");
  MassOptions o;
  o.density = density;
  o.mass = mass;
  return o;
}

py::dict mass_properties_dict(PythonMesh& m, std::optional<double> density,
                              std::optional<double> mass) {
  AnalysisOptions options;
  options.mass = mass_options(density, mass);
  options.topology = false;  // the mass figures do not depend on it (analyze.hpp)
  Analysis a;
  {
    py::gil_scoped_release release;
    a = analyze_mesh(m.mesh, m.source, options);
  }
  const MassProperties& p = a.mass;
  py::dict d;
  // trimesh's keys first (trimesh.Trimesh.mass_properties), then the rest of the front door's.
  d["volume"] = p.volume;
  d["mass"] = p.mass;
  d["density"] = p.density;
  d["center_mass"] = array_from(p.center_of_mass);
  d["inertia"] = array_from(p.inertia_com);
  d["surface_area"] = p.area;
  d["inertia_origin"] = array_from(p.inertia_origin);
  d["principal_inertia_components"] =
      array_from(Vec3d{p.principal.moments[0], p.principal.moments[1], p.principal.moments[2]});
  d["principal_inertia_vectors"] =
      array_from(Mat3{{{p.principal.axes[0].x, p.principal.axes[0].y, p.principal.axes[0].z},
                       {p.principal.axes[1].x, p.principal.axes[1].y, p.principal.axes[1].z},
                       {p.principal.axes[2].x, p.principal.axes[2].y, p.principal.axes[2].z}}});
  d["principal_motor"] = py::cast(p.principal_motor);
  d["gap_area"] = p.gap_area;
  d["warnings"] = a.warnings;
  return d;
}

py::list boundary_loops(PythonMesh& m) {
  const TopologyReport& t = m.topology();
  py::list loops;
  for (const BoundaryLoop& loop : t.boundary_loops) {
    std::vector<std::uint32_t> vertices;  // the tail vertex of each boundary half-edge, in order
    vertices.reserve(loop.half_edges.size());
    for (const std::uint32_t corner : loop.half_edges) vertices.push_back(m.mesh.corners[corner]);
    py::dict d;
    d["vertices"] =
        py::array_t<std::uint32_t>(static_cast<py::ssize_t>(vertices.size()), vertices.data());
    d["corners"] = py::array_t<std::uint32_t>(static_cast<py::ssize_t>(loop.half_edges.size()),
                                              loop.half_edges.data());
    d["closed"] = loop.closed;
    d["vector_area"] = array_from(loop.vector_area);
    d["area"] = loop.area;
    d["perimeter"] = loop.perimeter;
    loops.append(d);
  }
  return loops;
}

py::object analyze_file_json(const py::object& path_like, std::optional<double> density,
                             std::optional<double> mass, std::optional<double> weld_tolerance,
                             bool topology, std::optional<std::string> format, unsigned threads) {
  AnalysisOptions options;
  options.mass = mass_options(density, mass);
  options.mass.threads = threads;
  options.topology = topology;
  options.topology_options.weld_tolerance = weld_tolerance_from(weld_tolerance);
  options.format = format_from(format);
  const std::string path = py::str(py::module_::import("os").attr("fspath")(path_like));
  std::string text;
  {
    py::gil_scoped_release release;
    text = cli::props_json(analyze_file(path, options));
  }
  return json_to_python(text);
}

}  // namespace

void bind_mesh(py::module_& m) {
  py::class_<PythonMesh> mesh(m, "Mesh", R"(A polygon mesh: vertices and faces as numpy arrays.

Mesh(vertices, faces, weld_tolerance=None) copies float64 vertices of shape (n, 3) and faces
given as an (m, k) integer array or a sequence of polygons of any sizes (vertex indices,
counter-clockwise seen from outside). A row that is not finite, or an index out of range,
raises ValueError naming the row. Figures are computed on first use and kept: the arrays the
mesh exposes are read-only views.)");
  mesh.def(py::init(&from_arrays), py::arg("vertices"), py::arg("faces"),
           py::arg("weld_tolerance") = py::none());
  mesh.def_property_readonly(
          "vertices",
          [](py::object self) {
            auto& s = self.cast<PythonMesh&>();
            return view(&s.mesh.vertices.data()->x, s.mesh.vertices.size(), 3, self);
          },
          "(n, 3) float64 read-only view of the vertices (no copy).")
      .def_property_readonly(
          "faces",
          [](py::object self) -> py::object {
            auto& s = self.cast<PythonMesh&>();
            if (all_triangles(s.mesh))
              return view(s.mesh.corners.data(), s.mesh.face_count(), 3, self);
            py::list polygons;
            for (std::size_t f = 0; f < s.mesh.face_count(); ++f)
              polygons.append(py::array_t<std::uint32_t>(
                  static_cast<py::ssize_t>(s.mesh.face_size(f)), s.mesh.face(f)));
            return polygons;
          },
          "Triangles: an (m, 3) uint32 read-only view of the corners (no copy). Other polygons: "
          "a list of uint32 arrays, one a face.")
      .def_property_readonly(
          "corners",
          [](py::object self) {
            auto& s = self.cast<PythonMesh&>();
            return view(s.mesh.corners.data(), s.mesh.corners.size(), 1, self);
          },
          "uint32 read-only view of every face's vertex indices, face after face (no copy).")
      .def_property_readonly(
          "face_offsets",
          [](py::object self) {
            auto& s = self.cast<PythonMesh&>();
            return view(s.mesh.face_offsets.data(), s.mesh.face_offsets.size(), 1, self);
          },
          "uint32 read-only view: face f is corners[face_offsets[f]:face_offsets[f + 1]].")
      .def_property_readonly(
          "format", [](PythonMesh& s) { return std::string(format_name(s.source.format)); },
          "The format read ('stl-binary', 'obj', …; 'unknown' for arrays).")
      .def_property_readonly(
          "weld_tolerance", [](PythonMesh& s) { return s.weld_tolerance; },
          "The weld tolerance of the topology (0: bitwise-equal coordinates only).")
      .def_property_readonly(
          "triangles", [](PythonMesh& s) { return s.analyzed().mass.triangles; },
          "Triangles of the faces' fans: Σ (corners − 2).")
      .def_property_readonly(
          "area", [](PythonMesh& s) { return s.analyzed().mass.area; }, "Surface area.")
      .def_property_readonly(
          "volume", [](PythonMesh& s) { return s.analyzed().mass.volume; },
          "Signed volume: positive for a closed, outward-oriented surface (never abs()'d).")
      .def_property_readonly(
          "center_mass", [](PythonMesh& s) { return array_from(s.analyzed().mass.center_of_mass); },
          "Centre of mass (uniform density); NaN when the volume is 0.")
      .def_property_readonly(
          "moment_inertia", [](PythonMesh& s) { return array_from(s.analyzed().mass.inertia_com); },
          "Inertia tensor about the centre of mass at density 1, trimesh's convention: positive "
          "diagonal, off-diagonal entries minus the products of inertia (I_xy = -∫xy dm).")
      .def_property_readonly(
          "principal_inertia_components",
          [](PythonMesh& s) {
            const auto& pm = s.analyzed().mass.principal.moments;
            return array_from(Vec3d{pm[0], pm[1], pm[2]});
          },
          "Principal moments of inertia, ascending.")
      .def_property_readonly(
          "principal_inertia_vectors",
          [](PythonMesh& s) {
            const auto& a = s.analyzed().mass.principal.axes;
            return array_from(Mat3{
                {{a[0].x, a[0].y, a[0].z}, {a[1].x, a[1].y, a[1].z}, {a[2].x, a[2].y, a[2].z}}});
          },
          "Principal axes as rows (unit, right-handed), in the order of the components.")
      .def_property_readonly(
          "principal_motor", [](PythonMesh& s) { return s.analyzed().mass.principal_motor; },
          "The pga3.Motor M placing the principal frame: M o ~M is the centre of mass, "
          "M e_i ~M the principal axis i.")
      .def_property_readonly(
          "gap_area", [](PythonMesh& s) { return s.analyzed().mass.gap_area; },
          "½‖Σ F‖: 0 for a closed surface, the area a patch over the holes needs at least.")
      .def_property_readonly(
          "is_watertight",
          [](PythonMesh& s) {
            const TopologyReport& t = s.topology();
            return t.boundary_edges == 0 && t.nonmanifold_edges == 0;
          },
          "Every edge (after the weld) is shared by exactly two faces (trimesh's meaning: the "
          "winding is not looked at).")
      .def_property_readonly(
          "is_winding_consistent",
          [](PythonMesh& s) { return s.topology().orientation_consistent; },
          "No edge is used twice in the same direction.")
      .def_property_readonly(
          "is_volume", [](PythonMesh& s) { return s.analyzed().volume_valid.value_or(false); },
          "Volume, centre of mass and inertia describe a solid (closed, consistent, outward, "
          "not flat); `reasons` says why not.")
      .def_property_readonly(
          "reasons", [](PythonMesh& s) { return s.analyzed().reasons; },
          "Why the volume is not valid, in plain words.")
      .def_property_readonly(
          "warnings", [](PythonMesh& s) { return s.analyzed().warnings; },
          "The reader's repairs, float32 precision and other warnings.")
      .def_property_readonly("boundary_loops", &boundary_loops,
                             "The boundary loops: dicts of vertices (indices, in order), corners, "
                             "closed, vector_area, area and perimeter.")
      .def("mass_properties", &mass_properties_dict, py::kw_only(), py::arg("density") = py::none(),
           py::arg("mass") = py::none(),
           "trimesh's mass_properties dict (volume, mass, density, center_mass, inertia, "
           "surface_area) and inertia_origin, principal_inertia_components/vectors, "
           "principal_motor, gap_area, warnings. density or mass (then density = mass / volume).")
      .def(
          "props", [](PythonMesh& s) { return json_to_python(cli::props_json(s.analyzed())); },
          "The document of `pgamesh props --json` for this mesh, as a dict.")
      .def(
          "check",
          [](PythonMesh& s) {
            const Analysis& a = s.analyzed();
            return json_to_python(cli::json_text(cli::check_fields(s.mesh, s.source, a, nullptr)));
          },
          "The full topology report of `pgamesh check --json`, as a dict.")
      .def(py::pickle(
          [](const PythonMesh& s) {
            // The arrays (copies) and what the reader said of the source: a mesh sent to a Dask
            // worker gives the same figures there.
            const py::array_t<double> vertices(
                {static_cast<py::ssize_t>(s.mesh.vertices.size()), py::ssize_t{3}},
                &s.mesh.vertices.data()->x);
            return py::make_tuple(
                vertices,
                py::array_t<std::uint32_t>(static_cast<py::ssize_t>(s.mesh.corners.size()),
                                           s.mesh.corners.data()),
                py::array_t<std::uint32_t>(static_cast<py::ssize_t>(s.mesh.face_offsets.size()),
                                           s.mesh.face_offsets.data()),
                s.weld_tolerance, s.source.path, std::string(format_name(s.source.format)),
                s.source.single_precision, s.source.warnings);
          },
          [](const py::tuple& t) {
            if (t.size() != 8) throw py::value_error("not a pickled pgamesh.Mesh");
            auto m = std::make_unique<PythonMesh>();
            m->mesh.vertices = vertices_from(t[0]);
            const auto corners = t[1].cast<py::array_t<std::uint32_t, py::array::forcecast>>();
            const auto offsets = t[2].cast<py::array_t<std::uint32_t, py::array::forcecast>>();
            m->mesh.corners.assign(corners.data(), corners.data() + corners.size());
            m->mesh.face_offsets.assign(offsets.data(), offsets.data() + offsets.size());
            check_mesh_structure(m->mesh);  // std::out_of_range (IndexError) when inconsistent
            m->weld_tolerance = t[3].cast<double>();
            m->source.path = t[4].cast<std::string>();
            m->source.format = format_from_name(t[5].cast<std::string>());
            m->source.single_precision = t[6].cast<bool>();
            m->source.warnings = t[7].cast<std::vector<std::string>>();
            return m;
          }))
      .def("__repr__", [](PythonMesh& s) {
        return "<pgamesh.Mesh " + std::to_string(s.mesh.vertices.size()) + " vertices, " +
               std::to_string(s.mesh.face_count()) + " faces>";
      });

  m.def("load", &load, py::arg("source"), py::arg("weld_tolerance") = py::none(),
        py::arg("format") = py::none(),
        R"(Reads a mesh (STL, OBJ, PLY, OFF) from a path or from bytes.

weld_tolerance welds vertices closer than it for the topology (default: exact). format forces
the reader family ('stl', 'obj', 'ply', 'off'). Raises pgamesh.InputError naming the file and
the position of the problem. The GIL is released while reading.)");
  m.def("analyze_file", &analyze_file_json, py::arg("path"), py::kw_only(),
        py::arg("density") = py::none(), py::arg("mass") = py::none(),
        py::arg("weld_tolerance") = py::none(), py::arg("topology") = true,
        py::arg("format") = py::none(), py::arg("threads") = 0u,
        R"(The document of `pgamesh props --json FILE` as a dict, from the same code.

topology=False is `--fast` (STL streamed, no weld); threads=0 uses every core. The GIL is
released during the analysis.)");
}

}  // namespace pgamesh::python
