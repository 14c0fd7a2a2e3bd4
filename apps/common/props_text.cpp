// The readable report of `pgamesh props` and the <inertial> elements for URDF and MJCF.
#include <cmath>
#include <cstdio>

#include "pgamesh/io/mesh_format.hpp"
#include "props_report.hpp"
#include "text_append.hpp"

namespace pgamesh::cli {

namespace {

void matrix(std::string& out, const Mat3& m) {
  for (const auto& row : m)
    append(out, "    [ %22.15g %22.15g %22.15g ]\n", row[0], row[1], row[2]);
}

std::string topology_line(const std::optional<TopologyReport>& topology) {
  if (!topology) return "not computed (--no-topology)";
  const TopologyReport& t = *topology;
  std::string s = t.closed ? "closed" : "OPEN";
  s += t.orientation_consistent ? ", orientation consistent" : ", orientation INCONSISTENT";
  s += ", " + std::to_string(t.boundary_edges) + " boundary edges, " +
       std::to_string(t.nonmanifold_edges) + " non-manifold edges, " +
       std::to_string(t.components) + (t.components == 1 ? " component" : " components");
  if (t.duplicated_faces) s += ", " + std::to_string(t.duplicated_faces) + " duplicated faces";
  return s;
}

// " mm^3" and the like after a figure when the file states its unit, nothing otherwise.
std::string unit_suffix(LengthUnit u, int power) {
  if (u == LengthUnit::unspecified) return "";
  // Appended piece by piece: GCC 12's -Wrestrict misfires on `"literal" + std::string&&`.
  std::string s = " ";
  s += unit_name(u);
  if (power > 1) {
    s += '^';
    s += std::to_string(power);
  }
  return s;
}

// One line per part (3MF build item): its figures alone; the report above is the whole.
void parts_lines(std::string& out, const Analysis& r) {
  if (r.parts.empty()) return;
  append(out, "parts             %zu (each alone below; the figures above are the whole)\n",
         r.parts.size());
  const std::string u1 = unit_suffix(r.unit, 1), u2 = unit_suffix(r.unit, 2),
                    u3 = unit_suffix(r.unit, 3);
  for (std::size_t i = 0; i < r.parts.size(); ++i) {
    const PartAnalysis& p = r.parts[i];
    append(out, "  %zu '%s': %llu faces, area %.15g%s, volume %.15g%s, mass %.15g", i + 1,
           p.part.name.c_str(), static_cast<unsigned long long>(p.mass.faces), p.mass.area,
           u2.c_str(), p.mass.volume, u3.c_str(), p.mass.mass);
    if (std::isfinite(p.mass.center_of_mass.x))
      append(out, ", centre of mass %.15g %.15g %.15g%s", p.mass.center_of_mass.x,
             p.mass.center_of_mass.y, p.mass.center_of_mass.z, u1.c_str());
    append(out, "\n      topology %s\n", topology_line(p.topology).c_str());
    if (p.volume_valid.has_value() && !*p.volume_valid)
      for (const auto& reason : p.reasons) out += "      not a solid: " + reason + "\n";
  }
}

// An XML comment: "--" may not occur inside one.
std::string xml_comment(std::string text) {
  for (std::size_t k; (k = text.find("--")) != std::string::npos;) text.replace(k, 2, "- -");
  return "<!-- " + text + " -->\n";
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

}  // namespace

std::string props_text(const Analysis& r, bool about_origin) {
  const MassProperties& m = r.mass;
  std::string out;
  append(out, "file              %s (%s%s%s)\n", r.file.c_str(), format_name(r.format),
         r.single_precision ? ", float32" : "", r.streamed ? ", streamed" : "");
  if (r.unit != LengthUnit::unspecified)
    append(out, "unit              %s (stated by the file; lengths, areas, volumes in it)\n",
           unit_name(r.unit));
  const std::string u1 = unit_suffix(r.unit, 1), u2 = unit_suffix(r.unit, 2),
                    u3 = unit_suffix(r.unit, 3);
  append(out, "faces             %llu (%llu triangles), %llu vertices",
         static_cast<unsigned long long>(m.faces), static_cast<unsigned long long>(m.triangles),
         static_cast<unsigned long long>(m.vertices));
  if (r.topology)
    append(out, " (%llu after welding)", static_cast<unsigned long long>(r.topology->vertices));
  append(out, "\ntopology          %s\n", topology_line(r.topology).c_str());
  append(out, "area              %.15g%s\n", m.area, u2.c_str());
  append(out, "volume            %.15g%s (signed: positive for outward faces)\n", m.volume,
         u3.c_str());
  append(out, "density           %.15g%s\n", m.density,
         r.density_from_mass ? " (from the given mass)" : "");
  append(out, "mass              %.15g\n", m.mass);
  append(out, "gap area          %.15g%s (1/2 |sum of face carriers|: 0 when closed)\n", m.gap_area,
         u2.c_str());
  if (!std::isfinite(m.center_of_mass.x)) {
    out += "centre of mass    undefined (zero volume)\n";
  } else {
    append(out, "centre of mass    %.15g %.15g %.15g%s\n", m.center_of_mass.x, m.center_of_mass.y,
           m.center_of_mass.z, u1.c_str());
    out +=
        "inertia about the centre of mass (tensor; off-diagonals are MINUS the products of "
        "inertia, I_xy = -integral x y dm):\n";
    matrix(out, m.inertia_com);
    append(out,
           "products of inertia about the centre of mass (integral x y dm, ...): xy %.15g  "
           "yz %.15g  zx %.15g\n",
           m.products_com.xy, m.products_com.yz, m.products_com.zx);
    if (about_origin) {
      out += "inertia about the origin (same convention):\n";
      matrix(out, m.inertia_origin);
      append(out, "products of inertia about the origin: xy %.15g  yz %.15g  zx %.15g\n",
             m.products_origin.xy, m.products_origin.yz, m.products_origin.zx);
    }
    out += "principal moments (ascending) and unit axes (right-handed):\n";
    for (int i = 0; i < 3; ++i)
      append(out, "    I%d = %22.15g   axis %19.15f %19.15f %19.15f\n", i + 1,
             m.principal.moments[i], m.principal.axes[i].x, m.principal.axes[i].y,
             m.principal.axes[i].z);
    if (m.principal.degenerate)
      out +=
          "    (degenerate: two or more moments are equal within 1e-7 relative; the axes of "
          "equal moments are one choice among many)\n";
    const auto& q = m.principal_motor;
    append(out,
           "principal frame motor M = T R (M o ~M = centre of mass, M e_i ~M = axis i):\n    "
           "%.15g %+.15g e01 %+.15g e02 %+.15g e03 %+.15g e12 %+.15g e31 %+.15g e23 %+.15g e0123\n",
           q.s, q.e01, q.e02, q.e03, q.e12, q.e31, q.e23, q.e0123);
  }
  if (r.volume_valid.has_value() && !*r.volume_valid) {
    out += "NOT MEANINGFUL as a solid:\n";
    for (const auto& reason : r.reasons) out += "    " + reason + "\n";
  } else if (!r.volume_valid.has_value()) {
    out += "note: topology not computed, so closedness was not checked\n";
  }
  parts_lines(out, r);
  for (const auto& w : r.warnings) out += "warning: " + w + "\n";
  return out;
}

std::string props_urdf(const Analysis& r) {
  const MassProperties& m = r.mass;
  const Mat3& i = m.inertia_com;
  std::string head;
  append(head,
         "pgamesh props %s: URDF inertial. origin xyz = centre of mass in the mesh frame (rpy 0: "
         "axes of the mesh frame); inertia about the centre of mass, tensor entries: ixy = I_xy = "
         "-integral x y dm (URDF convention). density %.17g, mass %.17g.",
         r.file.c_str(), m.density, m.mass);
  std::string out = xml_comment(head) + not_meaningful_comment(r);
  append(out,
         "<inertial>\n"
         "  <origin xyz=\"%.17g %.17g %.17g\" rpy=\"0 0 0\"/>\n"
         "  <mass value=\"%.17g\"/>\n"
         "  <inertia ixx=\"%.17g\" ixy=\"%.17g\" ixz=\"%.17g\" iyy=\"%.17g\" iyz=\"%.17g\" "
         "izz=\"%.17g\"/>\n"
         "</inertial>\n",
         m.center_of_mass.x, m.center_of_mass.y, m.center_of_mass.z, m.mass, i[0][0], i[0][1],
         i[0][2], i[1][1], i[1][2], i[2][2]);
  return out;
}

std::string props_mjcf(const Analysis& r) {
  const MassProperties& m = r.mass;
  const Mat3& i = m.inertia_com;
  const auto q = quaternion(m.principal.rotor);
  std::string head;
  append(head,
         "pgamesh props %s: MJCF inertial. pos = centre of mass in the mesh frame; "
         "diaginertia = principal moments (ascending) about the centre of mass; quat (w x y z) "
         "turns the mesh frame into the principal frame (its axes are the principal axes). "
         "density %.17g. Equivalent: fullinertia=\"%.17g %.17g %.17g %.17g %.17g %.17g\" "
         "(ixx iyy izz ixy ixz iyz, tensor entries, ixy = -integral x y dm) with no quat.",
         r.file.c_str(), m.density, i[0][0], i[1][1], i[2][2], i[0][1], i[0][2], i[1][2]);
  std::string out = xml_comment(head) + not_meaningful_comment(r);
  append(out,
         "<inertial pos=\"%.17g %.17g %.17g\" quat=\"%.17g %.17g %.17g %.17g\" mass=\"%.17g\" "
         "diaginertia=\"%.17g %.17g %.17g\"/>\n",
         m.center_of_mass.x, m.center_of_mass.y, m.center_of_mass.z, q[0], q[1], q[2], q[3], m.mass,
         m.principal.moments[0], m.principal.moments[1], m.principal.moments[2]);
  return out;
}

}  // namespace pgamesh::cli
