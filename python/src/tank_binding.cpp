// pgamesh.Tank: fuel gauging of a closed mesh (pgamesh/tank, `pgamesh fuel`, docs/fuel.md). The
// state at one level is the dict of `pgamesh fuel --json` (apps/common/fuel_json), gauge tables
// and attitude grids are numpy arrays of the library's fuel states.
#include <memory>
#include <numbers>
#include <span>
#include <vector>

#include "bindings.hpp"
#include "fuel_json.hpp"
#include "json_text.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/tank/attitude.hpp"
#include "pgamesh/tank/fuel_index.hpp"
#include "pgamesh/tank/fuel_state.hpp"
#include "pgamesh/tank/fuel_sweep.hpp"
#include "pgamesh/tank/inverse_level.hpp"
#include "pgamesh/tank/tank.hpp"

namespace pgamesh::python {

namespace {

// The tank and its query index (which refers to the tank, so both live at fixed addresses).
struct PythonTank {
  std::unique_ptr<tank::Tank> tank;
  std::unique_ptr<tank::FuelIndex> index;
  std::vector<std::string> problems;  // tank_fitness's, when forced
};

std::unique_ptr<PythonTank> make(const py::object& mesh, bool force) {
  // The Mesh's arrays, read through its views: the tank is built from the same vertices and faces.
  const auto vertices =
      mesh.attr("vertices").cast<py::array_t<double, py::array::c_style | py::array::forcecast>>();
  const auto corners = mesh.attr("corners").cast<py::array_t<std::uint32_t>>();
  const auto offsets = mesh.attr("face_offsets").cast<py::array_t<std::uint32_t>>();
  Mesh m;
  const auto v = vertices.unchecked<2>();
  m.vertices.reserve(static_cast<std::size_t>(vertices.shape(0)));
  for (py::ssize_t i = 0; i < vertices.shape(0); ++i)
    m.vertices.push_back({v(i, 0), v(i, 1), v(i, 2)});
  m.corners.assign(corners.data(), corners.data() + corners.size());
  m.face_offsets.assign(offsets.data(), offsets.data() + offsets.size());
  auto t = std::make_unique<PythonTank>();
  {
    py::gil_scoped_release release;
    t->tank = std::make_unique<tank::Tank>(tank::make_tank(m));
    tank::TankFitness fitness = tank::tank_fitness(m, *t->tank);
    t->problems = std::move(fitness.problems);
    if (t->problems.empty() || force) t->index = std::make_unique<tank::FuelIndex>(*t->tank);
  }
  if (!t->index) {
    std::string why;
    for (const auto& p : t->problems) why += (why.empty() ? "" : "; ") + p;
    throw py::value_error("not a valid tank: " + why + " (force=True gauges it anyway)");
  }
  return t;
}

Vec3d up_from(const py::object& up) {
  return tank::unit_up(vec3_from(up, "up"));
}

py::object state_dict(const PythonTank& t, const tank::FuelState& st, Vec3d up) {
  cli::Json j;
  cli::write_fuel_state(j, st, tank::level_range(*t.tank, up));
  return json_to_python(cli::json_text(j));
}

py::object fuel(const PythonTank& t, const py::object& up_value, std::optional<double> level,
                std::optional<double> volume, std::optional<double> fraction) {
  if ((level ? 1 : 0) + (volume ? 1 : 0) + (fraction ? 1 : 0) != 1)
    throw py::value_error("give one of level, volume, fraction");
  const Vec3d up = up_from(up_value);
  tank::FuelState st;
  {
    py::gil_scoped_release release;
    const tank::LevelRange range = tank::level_range(*t.tank, up);
    if (level) {
      if (!(*level >= range.lowest && *level <= range.highest))
        throw std::domain_error("the level is outside the tank (its points lie from " +
                                std::to_string(range.lowest) + " to " +
                                std::to_string(range.highest) + " along up)");
      st = tank::fuel_naive(*t.tank, tank::FuelPlane{up, *level});
    } else {
      const tank::LevelSolution s = volume ? tank::level_for_volume(*t.index, up, *volume)
                                           : tank::level_for_fraction(*t.index, up, *fraction);
      st = t.index->query(tank::FuelPlane{up, s.level});
    }
  }
  return state_dict(t, st, up);
}

// Columns of fuel states as arrays, with `shape` leading.
py::dict columns(const std::vector<tank::FuelState>& rows, std::vector<py::ssize_t> shape) {
  auto with = [&](std::vector<py::ssize_t> tail) {
    std::vector<py::ssize_t> s = shape;
    s.insert(s.end(), tail.begin(), tail.end());
    return py::array_t<double>(s);
  };
  py::array_t<double> level = with({}), volume = with({}), fraction = with({}), wetted = with({}),
                      surface = with({}), ullage = with({}), com = with({3}),
                      inertia = with({3, 3});
  double* lv = level.mutable_data();
  double* vo = volume.mutable_data();
  double* fr = fraction.mutable_data();
  double* we = wetted.mutable_data();
  double* su = surface.mutable_data();
  double* ul = ullage.mutable_data();
  double* c = com.mutable_data();
  double* in = inertia.mutable_data();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const tank::FuelState& st = rows[i];
    lv[i] = st.plane.level, vo[i] = st.volume, fr[i] = st.fraction;
    we[i] = st.wetted_area, su[i] = st.surface_area, ul[i] = st.ullage_volume;
    const Vec3d p = st.has_center ? st.center_of_mass : Vec3d{nan, nan, nan};
    c[3 * i] = p.x, c[3 * i + 1] = p.y, c[3 * i + 2] = p.z;
    for (int r = 0; r < 3; ++r)
      for (int k = 0; k < 3; ++k)
        in[9 * i + 3 * r + k] = st.has_center ? st.inertia_com[r][k] : nan;
  }
  py::dict d;
  d["level"] = level, d["volume"] = volume, d["fraction"] = fraction;
  d["center_mass"] = com, d["inertia"] = inertia;
  d["wetted_area"] = wetted, d["surface_area"] = surface, d["ullage_volume"] = ullage;
  return d;
}

py::dict table(const PythonTank& t, const py::object& up_value, int n) {
  if (n < 1) throw py::value_error("n must be at least 1");
  const Vec3d up = up_from(up_value);
  std::vector<tank::FuelState> rows;
  {
    py::gil_scoped_release release;
    const std::vector<double> levels = tank::even_levels(tank::level_range(*t.tank, up), n);
    rows = tank::fuel_sweep(*t.tank, up, levels);
  }
  return columns(rows, {static_cast<py::ssize_t>(rows.size())});
}

py::dict attitudes(const PythonTank& t, const py::object& pitch_value, const py::object& roll_value,
                   std::optional<double> volume, std::optional<double> fraction,
                   const py::object& up_value) {
  if ((volume ? 1 : 0) + (fraction ? 1 : 0) != 1)
    throw py::value_error("give one of volume, fraction");
  const auto pitch =
      py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(pitch_value);
  const auto roll =
      py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(roll_value);
  if (!pitch || !roll || pitch.ndim() != 1 || roll.ndim() != 1)
    throw py::value_error("pitch_deg and roll_deg must be 1-D sequences of degrees");
  const Vec3d level_up = up_from(up_value);
  const double target = volume ? *volume : *fraction * t.tank->volume;
  std::vector<tank::FuelState> rows;
  std::vector<double> ups;
  {
    py::gil_scoped_release release;
    const double deg = std::numbers::pi / 180;
    for (py::ssize_t i = 0; i < pitch.shape(0); ++i)
      for (py::ssize_t k = 0; k < roll.shape(0); ++k) {
        // The up vector of this attitude and the level holding the volume (`pgamesh fuel
        // --pitch --roll --volume`).
        const Vec3d up = tank::up_from_attitude(level_up, pitch.at(i) * deg, roll.at(k) * deg);
        const tank::LevelSolution s = tank::level_for_volume(*t.index, up, target);
        rows.push_back(t.index->query(tank::FuelPlane{up, s.level}));
        ups.insert(ups.end(), {up.x, up.y, up.z});
      }
  }
  py::dict d = columns(rows, {pitch.shape(0), roll.shape(0)});
  py::array_t<double> up_array({pitch.shape(0), roll.shape(0), py::ssize_t{3}});
  std::copy(ups.begin(), ups.end(), up_array.mutable_data());
  d["up"] = up_array;
  return d;
}

}  // namespace

void bind_tank(py::module_& m) {
  py::class_<PythonTank>(m, "Tank", R"(A closed mesh prepared for fuel queries (docs/fuel.md).

Tank(mesh, force=False): the mesh must be closed, consistently oriented and outward (the rule of
`pgamesh fuel`), else ValueError lists why, unless force=True. Fuel is the part up·x <= level;
`up` is any non-zero vector (normalized). Figures at density 1 (mass = volume).)")
      .def(py::init(&make), py::arg("mesh"), py::kw_only(), py::arg("force") = false)
      .def_property_readonly(
          "volume", [](const PythonTank& t) { return t.tank->volume; }, "The tank's volume.")
      .def_property_readonly(
          "problems", [](const PythonTank& t) { return t.problems; },
          "Why the mesh is not a valid tank (empty unless forced).")
      .def("fuel", &fuel, py::arg("up"), py::kw_only(), py::arg("level") = py::none(),
           py::arg("volume") = py::none(), py::arg("fraction") = py::none(),
           "The fuel state at a level, or at the level holding a volume or a fraction of the "
           "tank: the dict of `pgamesh fuel --json` (level, volume, fraction, center_of_mass, "
           "inertia_com, wetted_area, surface_area, free surface, ullage).")
      .def(
          "level_for_volume",
          [](const PythonTank& t, const py::object& up, double volume) {
            const Vec3d u = up_from(up);
            py::gil_scoped_release release;
            return tank::level_for_volume(*t.index, u, volume).level;
          },
          py::arg("up"), py::arg("volume"),
          "The level up·x = level below which the tank holds `volume`.")
      .def("table", &table, py::arg("up"), py::arg("n"),
           "A gauge table of n + 1 evenly spaced levels from empty to full: a dict of arrays "
           "level, volume, fraction, wetted_area, surface_area, ullage_volume of shape (n + 1,), "
           "center_mass (n + 1, 3) and inertia (n + 1, 3, 3) (NaN where there is no fuel).")
      .def("attitudes", &attitudes, py::arg("pitch_deg"), py::arg("roll_deg"), py::kw_only(),
           py::arg("volume") = py::none(), py::arg("fraction") = py::none(),
           py::arg("up") = py::make_tuple(0.0, 0.0, 1.0),
           "The fuel of a fixed volume (or fraction) over a grid of attitudes (pitch about the "
           "lateral axis, nose up; roll about the forward axis, right side down; degrees): the "
           "arrays of `table` with shape (len(pitch_deg), len(roll_deg), …) and the up vectors.");
}

}  // namespace pgamesh::python
