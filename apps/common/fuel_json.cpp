#include "fuel_json.hpp"

#include <cmath>

#include "pgamesh/core/number_text.hpp"

namespace pgamesh::cli {

namespace {

// A CSV cell: the number as format_number prints it, empty when it is not finite.
std::string num(double v) {
  return std::isfinite(v) ? format_number(v) : std::string();
}

}  // namespace

void write_fuel_state(Json& w, const tank::FuelState& st, const tank::LevelRange& range,
                      double density) {
  w["level"] = json_number(st.plane.level);
  w["volume"] = json_number(st.volume);
  w["fraction"] = json_number(st.fraction);
  w["mass"] = json_number(density * st.volume);
  if (st.has_center) {
    w["center_of_mass"] = json_vec3(st.center_of_mass);
    Mat3 inertia = st.inertia_com;
    for (auto& row : inertia)
      for (double& x : row) x *= density;
    w["inertia_com"] = json_matrix3(inertia);
  } else {
    w["center_of_mass"] = nullptr;
    w["inertia_com"] = nullptr;
  }
  w["wetted_area"] = json_number(st.wetted_area);
  w["surface_area"] = json_number(st.surface_area);
  w["surface_centroid"] = st.surface.area > 0 ? json_vec3(st.surface.centroid) : Json(nullptr);
  const Json axis1 = json_vec3(st.surface.axis1), axis2 = json_vec3(st.surface.axis2);
  w["surface_axes"] =
      axis1.is_null() || axis2.is_null() ? Json(nullptr) : Json::array({axis1, axis2});
  const auto& m = st.surface.second;
  const bool moments = std::isfinite(m[0]) && std::isfinite(m[1]) && std::isfinite(m[2]);
  w["surface_second_moment"] =
      moments ? Json::array({Json::array({m[0], m[2]}), Json::array({m[2], m[1]})}) : Json(nullptr);
  w["surface_moment_transverse"] = json_number(m[1]);
  w["surface_moment_longitudinal"] = json_number(m[0]);
  w["ullage_volume"] = json_number(st.ullage_volume);
  w["ullage_length"] = json_number(range.highest - st.plane.level);
}

Json fuel_conventions() {
  Json c;
  c["plane"] = "up . x = level, up a unit vector in the tank frame; fuel is up . x <= level";
  c["tank_frame"] = "x forward, y left, z up (right-handed)";
  c["attitude"] =
      "pitch about the lateral axis, positive nose up, then roll about the forward axis, "
      "positive right side down; degrees; up = (sin p, sin r cos p, cos r cos p) for a level "
      "up of +z";
  c["density"] =
      "mass per unit volume (top-level density; 1 unless --density or --mass): mass = "
      "density x volume, inertia = density x the volume's second moments";
  c["inertia"] =
      "tensor about the centre of mass, off-diagonals are minus the products of "
      "inertia (I_xy = -integral of x y dV)";
  c["surface_axes"] = "axis1 = the tank x axis projected onto the free surface, axis2 = up x axis1";
  c["surface_second_moment"] =
      "[[int s1^2, int s1 s2], [int s1 s2, int s2^2]] dA about the surface centroid; "
      "transverse = int s2^2 (about axis1), longitudinal = int s1^2 (about axis2)";
  c["units"] =
      "lengths in the mesh file's unit L: areas L^2, volumes L^3, moments of area L^4, "
      "mass in the density's unit times L^3, inertia mass x L^2";
  return c;
}

std::string fuel_csv_columns(bool attitude) {
  std::string s = attitude ? "pitch_deg,roll_deg," : "";
  return s +
         "level,volume,fraction,com_x,com_y,com_z,wetted_area,surface_area,"
         "surface_moment_transverse,surface_moment_longitudinal,surface_moment_product,"
         "ullage_length,ullage_volume,mass";
}

std::string fuel_csv_row(const tank::FuelState& st, const tank::LevelRange& range, bool attitude,
                         double pitch_deg, double roll_deg, double density) {
  std::string s;
  if (attitude) s += num(pitch_deg) + "," + num(roll_deg) + ",";
  const double nan = std::nan("");
  const Vec3d c = st.has_center ? st.center_of_mass : Vec3d{nan, nan, nan};
  const auto& m = st.surface.second;
  for (double v :
       {st.plane.level, st.volume, st.fraction, c.x, c.y, c.z, st.wetted_area, st.surface_area,
        m[1], m[0], m[2], range.highest - st.plane.level, st.ullage_volume, density * st.volume})
    s += num(v) + ",";
  s.pop_back();
  return s;
}

}  // namespace pgamesh::cli
