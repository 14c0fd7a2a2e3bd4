// The robot-description exports of `pgamesh props`: URDF and MJCF <inertial> elements and an
// SDFormat model, always in SI units (metres, kilograms; docs/mass-properties.md, "Exports"), each
// with the mesh element that places the file in the description at the scale of its unit.
#include <array>
#include <cmath>
#include <filesystem>

#include "pgamesh/core/units.hpp"
#include "props_report.hpp"
#include "text_append.hpp"

namespace pgamesh::cli {

namespace {

// An XML comment: "--" may not occur inside one.
std::string xml_comment(std::string text) {
  for (std::size_t k; (k = text.find("--")) != std::string::npos;) text.replace(k, 2, "- -");
  return "<!-- " + text + " -->\n";
}

// Text for an XML attribute or element.
std::string xml_escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

// The warning a forced export carries inside the file, where it travels with the figures: the
// front door's reasons the body is not a valid solid (pgamesh props refuses such a body unless
// --force).
std::string not_meaningful_comment(const Analysis& r) {
  if (r.volume_valid.value_or(false)) return "";
  std::string s =
      "WARNING: forced output, not a valid solid; these figures do not describe a body:";
  for (const auto& reason : r.reasons) s += " " + reason + ";";
  return xml_comment(s);
}

// The rotor's quaternion (w, x, y, z): R = cos(θ/2) − sin(θ/2)(a_x e23 + a_y e31 + a_z e12) turns
// by +θ about a (docs/conventions.md §7), the quaternion
// cos(θ/2) + sin(θ/2)(a_x i + a_y j + a_z k).
std::array<double, 4> quaternion(const pga3::Motor<double>& r) {
  return {r.s, -r.e23, -r.e31, -r.e12};
}

// The file as a file:// URI of its absolute path, and a name for the model and its mesh.
std::string mesh_uri(const Analysis& r) {
  if (r.file == "-") return "";
  return "file://" + xml_escaped(std::filesystem::absolute(r.file).lexically_normal().string());
}
std::string mesh_name(const Analysis& r) {
  const std::string stem = std::filesystem::path(r.file).stem().string();
  return xml_escaped(stem.empty() || r.file == "-" ? "mesh" : stem);
}

}  // namespace

SiInertial si_inertial(const Analysis& r) {
  // docs/conventions.md §14. A length in the file's unit is s metres. With --density ρ (kg/m³): m =
  // ρ V s³ and I = ρ ∫ r² dV s⁵, the report's figures (computed with the number ρ) scaled by s³ and
  // s⁵. With
  // --mass M (kg): m = M, ρ = M / (V s³), I = (M / V) ∫ r² dV s², the report's inertia × s².
  const double s = metres_per_unit(r.unit);
  const MassProperties& m = r.mass;
  SiInertial si;
  si.scale = s;
  si.unit_assumed = r.unit == LengthUnit::unspecified;
  const double mass_factor = r.density_from_mass ? 1 : s * s * s;
  const double inertia_factor = r.density_from_mass ? s * s : s * s * s * s * s;
  si.mass = m.mass * mass_factor;
  si.density = r.density_from_mass ? m.density / (s * s * s) : m.density;
  si.center_of_mass = m.center_of_mass * s;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) si.inertia[i][j] = m.inertia_com[i][j] * inertia_factor;
    si.moments[i] = m.principal.moments[i] * inertia_factor;
  }
  return si;
}

std::string props_urdf(const Analysis& r) {
  const SiInertial si = si_inertial(r);
  const Mat3& i = si.inertia;
  std::string head;
  append(head,
         "pgamesh props %s: URDF inertial in SI units (m, kg, kg m^2; the file's %s scaled by "
         "%.17g). origin xyz = centre of mass in the mesh frame (rpy 0: axes of the mesh frame); "
         "inertia about the centre of mass, tensor entries: ixy = I_xy = -integral x y dm (URDF "
         "convention). density %.17g kg/m^3, mass %.17g kg.",
         r.file.c_str(), unit_name(r.unit), si.scale, si.density, si.mass);
  std::string out = xml_comment(head) + not_meaningful_comment(r);
  append(out,
         "<inertial>\n"
         "  <origin xyz=\"%.17g %.17g %.17g\" rpy=\"0 0 0\"/>\n"
         "  <mass value=\"%.17g\"/>\n"
         "  <inertia ixx=\"%.17g\" ixy=\"%.17g\" ixz=\"%.17g\" iyy=\"%.17g\" iyz=\"%.17g\" "
         "izz=\"%.17g\"/>\n"
         "</inertial>\n",
         si.center_of_mass.x, si.center_of_mass.y, si.center_of_mass.z, si.mass, i[0][0], i[0][1],
         i[0][2], i[1][1], i[1][2], i[2][2]);
  const std::string uri = mesh_uri(r);
  if (!uri.empty())
    for (const char* element : {"visual", "collision"})
      append(out,
             "<%s>\n  <geometry>\n    <mesh filename=\"%s\" scale=\"%.17g %.17g %.17g\"/>\n"
             "  </geometry>\n</%s>\n",
             element, uri.c_str(), si.scale, si.scale, si.scale, element);
  return out;
}

std::string props_mjcf(const Analysis& r) {
  const SiInertial si = si_inertial(r);
  const Mat3& i = si.inertia;
  const auto q = quaternion(r.mass.principal.rotor);
  std::string head;
  append(head,
         "pgamesh props %s: MJCF inertial in SI units (m, kg, kg m^2; the file's %s scaled by "
         "%.17g). pos = centre of mass in the mesh frame; diaginertia = principal moments "
         "(ascending) about the centre of mass; quat (w x y z) turns the mesh frame into the "
         "principal frame (its axes are the principal axes). density %.17g kg/m^3. Equivalent: "
         "fullinertia=\"%.17g %.17g %.17g %.17g %.17g %.17g\" (ixx iyy izz ixy ixz iyz, tensor "
         "entries, ixy = -integral x y dm) with no quat.",
         r.file.c_str(), unit_name(r.unit), si.scale, si.density, i[0][0], i[1][1], i[2][2],
         i[0][1], i[0][2], i[1][2]);
  std::string out = xml_comment(head) + not_meaningful_comment(r);
  append(out,
         "<inertial pos=\"%.17g %.17g %.17g\" quat=\"%.17g %.17g %.17g %.17g\" mass=\"%.17g\" "
         "diaginertia=\"%.17g %.17g %.17g\"/>\n",
         si.center_of_mass.x, si.center_of_mass.y, si.center_of_mass.z, q[0], q[1], q[2], q[3],
         si.mass, si.moments[0], si.moments[1], si.moments[2]);
  const std::string uri = mesh_uri(r);
  if (!uri.empty())
    append(out, "%s<mesh name=\"%s\" file=\"%s\" scale=\"%.17g %.17g %.17g\"/>\n",
           xml_comment("for the <asset> element; the body's geom: <geom type=\"mesh\" mesh=\"" +
                       mesh_name(r) + "\"/>")
               .c_str(),
           mesh_name(r).c_str(), uri.substr(7).c_str(), si.scale, si.scale, si.scale);
  return out;
}

std::string props_sdf(const Analysis& r) {
  const SiInertial si = si_inertial(r);
  const Mat3& i = si.inertia;
  const std::string name = mesh_name(r);
  std::string head;
  append(head,
         "pgamesh props %s: SDFormat model in SI units (m, kg, kg m^2; the file's %s scaled by "
         "%.17g). inertial pose = centre of mass in the link frame (the mesh frame), axes of the "
         "mesh frame; inertia about the centre of mass, tensor entries: ixy = -integral x y dm. "
         "density %.17g kg/m^3.",
         r.file.c_str(), unit_name(r.unit), si.scale, si.density);
  std::string out = "<?xml version=\"1.0\"?>\n" + xml_comment(head) + not_meaningful_comment(r);
  append(out,
         "<sdf version=\"1.7\">\n"
         "  <model name=\"%s\">\n"
         "    <link name=\"%s\">\n"
         "      <inertial>\n"
         "        <pose>%.17g %.17g %.17g 0 0 0</pose>\n"
         "        <mass>%.17g</mass>\n"
         "        <inertia>\n"
         "          <ixx>%.17g</ixx>\n          <ixy>%.17g</ixy>\n          <ixz>%.17g</ixz>\n"
         "          <iyy>%.17g</iyy>\n          <iyz>%.17g</iyz>\n          <izz>%.17g</izz>\n"
         "        </inertia>\n"
         "      </inertial>\n",
         name.c_str(), name.c_str(), si.center_of_mass.x, si.center_of_mass.y, si.center_of_mass.z,
         si.mass, i[0][0], i[0][1], i[0][2], i[1][1], i[1][2], i[2][2]);
  const std::string uri = mesh_uri(r);
  if (!uri.empty())
    for (const char* element : {"collision", "visual"})
      append(out,
             "      <%s name=\"%s\">\n"
             "        <geometry>\n"
             "          <mesh>\n"
             "            <uri>%s</uri>\n"
             "            <scale>%.17g %.17g %.17g</scale>\n"
             "          </mesh>\n"
             "        </geometry>\n"
             "      </%s>\n",
             element, element, uri.c_str(), si.scale, si.scale, si.scale, element);
  out += "    </link>\n  </model>\n</sdf>\n";
  return out;
}

}  // namespace pgamesh::cli
