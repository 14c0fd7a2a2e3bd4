#include "fuel_json.hpp"

#include <cmath>
#include <cstdio>

namespace pgamesh::cli {

namespace {

std::string num(double v) {
  if (!std::isfinite(v)) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace

void write_fuel_state(JsonWriter& w, const tank::FuelState& st, const tank::LevelRange& range,
                      double density) {
  w.number("level", st.plane.level);
  w.number("volume", st.volume);
  w.number("fraction", st.fraction);
  w.number("mass", density * st.volume);
  if (st.has_center) {
    w.vec3("center_of_mass", st.center_of_mass);
    Mat3 inertia = st.inertia_com;
    for (auto& row : inertia)
      for (double& x : row) x *= density;
    w.matrix3("inertia_com", inertia);
  } else {
    w.null("center_of_mass");
    w.null("inertia_com");
  }
  w.number("wetted_area", st.wetted_area);
  w.number("surface_area", st.surface_area);
  if (st.surface.area > 0) {
    w.vec3("surface_centroid", st.surface.centroid);
  } else {
    w.null("surface_centroid");
  }
  w.begin_array("surface_axes").vec3(st.surface.axis1).vec3(st.surface.axis2).end_array();
  const auto& m = st.surface.second;
  w.begin_array("surface_second_moment")
      .begin_array()
      .number(m[0])
      .number(m[2])
      .end_array()
      .begin_array()
      .number(m[2])
      .number(m[1])
      .end_array()
      .end_array();
  w.number("surface_moment_transverse", m[1]);
  w.number("surface_moment_longitudinal", m[0]);
  w.number("ullage_volume", st.ullage_volume);
  w.number("ullage_length", range.highest - st.plane.level);
}

void write_fuel_conventions(JsonWriter& w) {
  w.begin_object("conventions");
  w.string("plane", "up . x = level, up a unit vector in the tank frame; fuel is up . x <= level");
  w.string("tank_frame", "x forward, y left, z up (right-handed)");
  w.string("attitude",
           "pitch about the lateral axis, positive nose up, then roll about the forward axis, "
           "positive right side down; degrees; up = (sin p, sin r cos p, cos r cos p) for a level "
           "up of +z");
  w.string("density",
           "mass per unit volume (top-level density; 1 unless --density or --mass): mass = "
           "density x volume, inertia = density x the volume's second moments");
  w.string("inertia",
           "tensor about the centre of mass, off-diagonals are minus the products of "
           "inertia (I_xy = -integral of x y dV)");
  w.string("surface_axes",
           "axis1 = the tank x axis projected onto the free surface, axis2 = up x axis1");
  w.string("surface_second_moment",
           "[[int s1^2, int s1 s2], [int s1 s2, int s2^2]] dA about the surface centroid; "
           "transverse = int s2^2 (about axis1), longitudinal = int s1^2 (about axis2)");
  w.string("units",
           "lengths in the mesh file's unit L: areas L^2, volumes L^3, moments of area L^4, "
           "mass in the density's unit times L^3, inertia mass x L^2");
  w.end_object();
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
