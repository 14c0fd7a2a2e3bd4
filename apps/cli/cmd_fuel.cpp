// `pgamesh fuel FILE --up X,Y,Z (--level H | --volume V | --fraction F | --table N |
// --volumes V1,V2,...) [--pitch DEG[,DEG...]] [--roll DEG[,DEG...]] [--accel AX,AY,AZ]
// [--density RHO | --mass M] [--json | --csv] [--force]`: fuel gauging of a closed tank
// (docs/fuel.md).
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <memory>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "commands.hpp"
#include "fuel_json.hpp"
#include "json_text.hpp"
#include "pgamesh/analysis/analyze.hpp"
#include "pgamesh/core/input_error.hpp"
#include "pgamesh/io/mesh_format.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/mesh/topology/topology.hpp"
#include "pgamesh/mesh/weld/weld.hpp"
#include "pgamesh/tank/attitude.hpp"
#include "pgamesh/tank/fuel_index.hpp"
#include "pgamesh/tank/fuel_sweep.hpp"
#include "pgamesh/tank/inverse_level.hpp"
#include "text_append.hpp"

namespace pgamesh::cli {

namespace {

struct Options {
  std::string file;
  LengthUnit unit = LengthUnit::unspecified;  // --unit: of a file that states none
  Vec3d up{0, 0, 1};
  bool up_given = false;
  std::vector<double> pitch{0}, roll{0};
  bool attitude = false;
  bool accel_given = false;
  Vec3d accel{};
  enum class Query { none, level, volume, fraction, table, volumes } query = Query::none;
  double value = 0;
  int table = 0;
  std::vector<double> volumes;
  std::optional<double> density, mass;
  double weld_tolerance = 0;  // > 0: the tank is the mesh welded within it
  bool json = false, csv = false, force = false;
};

// The options as parsed, before the query and the attitude are told apart.
struct FuelArgs {
  Options o;
  std::optional<double> level, volume, fraction;
  unsigned long long table = 0;
  CLI::Option *up = nullptr, *pitch = nullptr, *roll = nullptr, *accel = nullptr,
              *table_given = nullptr, *volumes = nullptr;
};

Options resolve(const FuelArgs& a) {
  Options o = a.o;
  o.up_given = a.up->count() > 0;
  o.attitude = a.pitch->count() + a.roll->count() > 0;
  o.accel_given = a.accel->count() > 0;
  const int queries = a.level.has_value() + a.volume.has_value() + a.fraction.has_value() +
                      (a.table_given->count() > 0) + (a.volumes->count() > 0);
  if (queries > 1)
    throw UsageError("give only one of --level, --volume, --fraction, --table, --volumes");
  if (queries == 0)
    throw UsageError("give one of --level, --volume, --fraction, --table, --volumes");
  if (a.level) {
    o.query = Options::Query::level;
    o.value = *a.level;
  } else if (a.volume) {
    o.query = Options::Query::volume;
    o.value = *a.volume;
  } else if (a.fraction) {
    o.query = Options::Query::fraction;
    o.value = *a.fraction;
  } else if (a.table_given->count() > 0) {
    o.query = Options::Query::table;
    o.table = static_cast<int>(a.table);
  } else {
    o.query = Options::Query::volumes;
  }
  if (o.json && o.csv) throw UsageError("--json and --csv exclude each other");
  if (o.density && o.mass) throw UsageError("give --density or --mass, not both");
  if (o.accel_given && (o.up_given || o.attitude))
    throw UsageError("--accel gives the up vector: do not combine it with --up, --pitch, --roll");
  if (o.pitch.size() * o.roll.size() > 100000) throw UsageError("at most 100000 attitudes");
  return o;
}

struct Attitude {
  double pitch_deg = 0, roll_deg = 0;
  Vec3d up{};
};

std::vector<Attitude> attitudes(const Options& o) {
  std::vector<Attitude> out;
  if (o.accel_given) {
    out.push_back({0, 0, tank::up_from_gravity(o.accel)});
    return out;
  }
  const double deg = std::numbers::pi / 180;
  for (double p : o.pitch)
    for (double r : o.roll) out.push_back({p, r, tank::up_from_attitude(o.up, p * deg, r * deg)});
  return out;
}

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

// Whether the mesh is fit to be a tank, from the topology report `pgamesh check` and `props` use.
struct TankCheck {
  TopologyReport topology;
  bool fit = false;
  bool forced = false;                // unfit, computed anyway (--force)
  std::vector<std::string> problems;  // why unfit (tank::TankFitness::problems)
};

// The mesh as gauged: as read, or welded within --weld-tolerance (a CAD export closed only up to
// its rounding), with what the weld did.
struct GaugedMesh {
  Mesh mesh;
  WeldMap weld;
};

// The tank's fields of the document: the same names as `pgamesh props` and `pgamesh check` for the
// same things (docs/json.md).
void write_header(Json& w, const Options& o, const Analysis& analysis, const GaugedMesh& gauged,
                  const tank::Tank& t, const TankCheck& check, double density) {
  w["file"] = o.file;
  w["format"] = format_name(analysis.format);
  w["unit"] = unit_name(analysis.unit);
  w["triangles"] = t.triangles.size();
  w["faces"] = gauged.mesh.face_count();
  w["weld"] = Json{{"tolerance", json_number(o.weld_tolerance)},
                   {"merged", gauged.weld.merged},
                   {"max_moved", json_number(gauged.weld.max_moved)}};
  w["tank_volume"] = json_number(t.volume);
  w["density"] = json_number(density);
  w["tank_mass"] = json_number(density * t.volume);
  const TopologyReport& r = check.topology;
  w["topology"] = Json{{"closed", r.closed},
                       {"orientation_consistent", r.orientation_consistent},
                       {"boundary_edges", r.boundary_edges},
                       {"nonmanifold_edges", r.nonmanifold_edges},
                       {"inconsistent_edges", r.inconsistent_edges},
                       {"gap_area", json_number(r.gap_area)},
                       {"self_intersecting_pairs", r.self_intersecting_pairs},
                       {"notes", json_strings(r.notes)}};
  w["volume_valid"] = check.fit;
  w["reasons"] = json_strings(check.problems);
  w["forced"] = check.forced;
  w["warnings"] = json_strings(analysis.warnings);
  w["conventions"] = fuel_conventions();
}

void write_attitude(Json& w, const Options& o, const Attitude& a) {
  w["up"] = json_vec3(a.up);
  if (o.attitude) {
    w["pitch_deg"] = json_number(a.pitch_deg);
    w["roll_deg"] = json_number(a.roll_deg);
  }
}

void print_state(std::string& out, const tank::FuelState& st, const tank::LevelRange& range,
                 double density) {
  append(out, "  level           %s (tank from %s to %s along up)\n", fmt(st.plane.level).c_str(),
         fmt(range.lowest).c_str(), fmt(range.highest).c_str());
  append(out, "  volume          %s (fraction %s), ullage %s\n", fmt(st.volume).c_str(),
         fmt(st.fraction).c_str(), fmt(st.ullage_volume).c_str());
  if (density != 1)
    append(out, "  mass            %s (density %s)\n", fmt(density * st.volume).c_str(),
           fmt(density).c_str());
  if (st.has_center)
    append(out, "  centre of mass  %s %s %s\n", fmt(st.center_of_mass.x).c_str(),
           fmt(st.center_of_mass.y).c_str(), fmt(st.center_of_mass.z).c_str());
  append(out, "  wetted area     %s\n", fmt(st.wetted_area).c_str());
  append(out, "  free surface    %s, moments of area: transverse %s, longitudinal %s\n",
         fmt(st.surface_area).c_str(), fmt(st.surface.second[1]).c_str(),
         fmt(st.surface.second[0]).c_str());
}

// The tank must be fit for gauging (tank::tank_fitness, the rule the viewer applies too): refused
// with its topology figures and the reasons unless --force.
TankCheck check_tank(const Options& o, const Mesh& mesh, const tank::Tank& t) {
  tank::TankFitness fitness = tank::tank_fitness(mesh, t);
  TankCheck c;
  c.topology = std::move(fitness.topology);
  c.fit = fitness.fit;
  c.problems = fitness.problems;
  if (c.fit) return c;
  c.forced = o.force;
  const TopologyReport& r = c.topology;
  std::fprintf(stderr,
               "%s: %s: closed %s, orientation %s, %zu boundary edges, %zu non-manifold, %zu "
               "inconsistent, gap area %.17g, volume %.17g\n",
               o.file.c_str(), o.force ? "warning: not a closed outward tank" : "not a tank",
               r.closed ? "yes" : "no", r.orientation_consistent ? "consistent" : "INCONSISTENT",
               r.boundary_edges, r.nonmanifold_edges, r.inconsistent_edges, r.gap_area, t.volume);
  for (const auto& problem : fitness.problems)
    std::fprintf(stderr, "%s: %s\n", o.file.c_str(), problem.c_str());
  std::fprintf(stderr,
               o.force ? "%s: computing anyway (--force)\n"
                       : "%s: a tank must be closed and outward-oriented (--force to proceed)\n",
               o.file.c_str());
  return c;
}

GaugedMesh gauged_mesh(const Options& o, MeshSource& source) {
  Mesh read = read_mesh(o.file, &source);
  if (o.weld_tolerance == 0) return {std::move(read), {}};
  WeldResult welded = weld(std::move(read), o.weld_tolerance);
  return {std::move(welded.mesh), std::move(welded.map)};
}

int run(const Options& o) {
  MeshSource source;
  const GaugedMesh gauged = gauged_mesh(o, source);
  const Mesh& mesh = gauged.mesh;
  // The front door's reading of the mesh, for what it says of every file (the reader's repairs,
  // float32 precision) and its refusal of coordinates whose figures overflow; the tank's fitness
  // is tank::tank_fitness's rule below.
  AnalysisOptions analysis_options;
  analysis_options.topology = false;
  analysis_options.unit = o.unit;
  const Analysis analysis = analyze_mesh(mesh, source, analysis_options);
  tank::Tank t;
  try {
    t = tank::make_tank(mesh);
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "%s: %s\n", o.file.c_str(), e.what());
    return 1;
  }
  const TankCheck check = check_tank(o, mesh, t);
  if (!check.fit && !check.forced) return 1;
  if (o.mass && !(t.volume > 0)) {
    std::fprintf(stderr, "%s: --mass needs a tank with a positive volume\n", o.file.c_str());
    return 1;
  }
  // --mass M is the mass of the full tank (as `pgamesh props --mass` is the mesh's).
  const double density = o.mass ? *o.mass / t.volume : o.density.value_or(1.0);
  const std::vector<Attitude> atts = attitudes(o);
  const bool grid = atts.size() > 1;
  const bool tty = isatty(fileno(stderr));
  // Everything for stdout is built here and printed only once the command has succeeded: a
  // level outside the tank or a volume it cannot hold leaves stdout empty, never half a table.
  std::string out;
  // The document: the tank's fields, then one attitude's (or "attitudes", one object each).
  Json doc;
  write_header(doc, o, analysis, gauged, t, check, density);
  if (grid) doc["attitudes"] = Json::array();
  if (o.csv) {
    append(out,
           "# pgamesh fuel: %s\n# fuel is up.x <= level (up a unit vector, tank frame x "
           "forward, y left, z up); ullage_length = highest point - level\n"
           "# units: lengths in the mesh unit L, areas L^2, volumes L^3, moments of area "
           "L^4; mass = density x volume in the unit of the density times L^3\n"
           "# unit %s\n# density %.17g\n# tank_volume %.17g\n",
           o.file.c_str(), unit_name(analysis.unit), density, t.volume);
    if (o.weld_tolerance > 0)
      append(out, "# weld_tolerance %.17g merged %zu max_moved %.17g\n", o.weld_tolerance,
             gauged.weld.merged, gauged.weld.max_moved);
    // A forced table says so inside the file, where it travels with the figures.
    for (const auto& problem : check.problems)
      append(out, "# warning: forced (--force), not a valid tank: %s\n", problem.c_str());
  }
  if (!o.json && !o.csv && o.weld_tolerance > 0)
    append(out, "%s: welded within %s: %zu vertices merged, moved at most %s\n", o.file.c_str(),
           fmt(o.weld_tolerance).c_str(), gauged.weld.merged, fmt(gauged.weld.max_moved).c_str());
  const bool csv_attitude = o.attitude || grid;
  std::unique_ptr<tank::FuelIndex> index;
  for (std::size_t ai = 0; ai < atts.size(); ++ai) {
    const Attitude& a = atts[ai];
    const tank::LevelRange range = tank::level_range(t, a.up);
    Json attitude_fields;
    Json& w = grid ? attitude_fields : doc;
    if (o.csv && (ai == 0 || grid))
      append(out, "# up %.17g,%.17g,%.17g%s\n", a.up.x, a.up.y, a.up.z,
             o.attitude ? (" pitch " + fmt(a.pitch_deg) + " roll " + fmt(a.roll_deg)).c_str() : "");
    write_attitude(w, o, a);
    if (!o.json && !o.csv)
      append(
          out, "%s: up %s %s %s%s, lengths in %s\n", o.file.c_str(), fmt(a.up.x).c_str(),
          fmt(a.up.y).c_str(), fmt(a.up.z).c_str(),
          o.attitude
              ? (" (pitch " + fmt(a.pitch_deg) + " deg, roll " + fmt(a.roll_deg) + " deg)").c_str()
              : "",
          unit_name(analysis.unit));
    switch (o.query) {
      case Options::Query::level: {
        if (o.value < range.lowest || o.value > range.highest) {
          std::fprintf(stderr,
                       "%s: level %s is %s the tank (its points lie from %s to %s along up): the "
                       "tank would be %s\n",
                       o.file.c_str(), fmt(o.value).c_str(),
                       o.value < range.lowest ? "below" : "above", fmt(range.lowest).c_str(),
                       fmt(range.highest).c_str(), o.value < range.lowest ? "empty" : "full");
          return 1;
        }
        const tank::FuelState st = tank::fuel_naive(t, tank::FuelPlane{a.up, o.value});
        if (o.csv) {
          if (ai == 0) append(out, "%s\n", fuel_csv_columns(csv_attitude).c_str());
          append(out, "%s\n",
                 fuel_csv_row(st, range, csv_attitude, a.pitch_deg, a.roll_deg, density).c_str());
        } else if (o.json) {
          write_fuel_state(w, st, range, density);
        } else {
          print_state(out, st, range, density);
        }
        break;
      }
      case Options::Query::volume:
      case Options::Query::fraction:
      case Options::Query::volumes: {
        if (!index) index = std::make_unique<tank::FuelIndex>(t);
        std::vector<double> targets =
            o.query == Options::Query::volumes ? o.volumes : std::vector<double>{o.value};
        if (o.query == Options::Query::fraction) {
          if (!(o.value >= 0 && o.value <= 1))
            throw std::domain_error("the fraction " + fmt(o.value) + " is outside [0, 1]");
          targets[0] = o.value * t.volume;
        }
        Json rows = Json::array();
        if (o.csv && (ai == 0))
          append(out, "target_volume,iterations,%s\n", fuel_csv_columns(csv_attitude).c_str());
        for (double v : targets) {
          const tank::LevelSolution s = tank::level_for_volume(*index, a.up, v);
          const tank::FuelState st = index->query(tank::FuelPlane{a.up, s.level});
          if (o.csv) {
            append(out, "%.17g,%d,%s\n", v, s.iterations,
                   fuel_csv_row(st, range, csv_attitude, a.pitch_deg, a.roll_deg, density).c_str());
          } else if (o.json) {
            Json row;
            Json& target = o.query == Options::Query::volumes ? row : w;
            target["target_volume"] = json_number(v);
            target["iterations"] = s.iterations;
            write_fuel_state(target, st, range, density);
            if (o.query == Options::Query::volumes) rows.push_back(std::move(row));
          } else {
            append(out, "  target volume   %s (%d fuel queries)\n", fmt(v).c_str(), s.iterations);
            print_state(out, st, range, density);
          }
        }
        if (o.json && o.query == Options::Query::volumes) w["rows"] = std::move(rows);
        break;
      }
      case Options::Query::table: {
        const std::vector<double> levels = tank::even_levels(range, o.table);
        // Progress on a terminal for long tables (stderr, overwritten in place).
        const bool show = tty && !grid && levels.size() >= 100000;
        const auto rows = tank::fuel_sweep(t, a.up, levels, [&](std::size_t done, std::size_t n) {
          if (show) std::fprintf(stderr, "\rpgamesh fuel: level %zu of %zu", done, n);
        });
        if (show) std::fprintf(stderr, "\n");
        if (o.csv) {
          if (ai == 0) append(out, "%s\n", fuel_csv_columns(csv_attitude).c_str());
          for (const auto& st : rows)
            append(out, "%s\n",
                   fuel_csv_row(st, range, csv_attitude, a.pitch_deg, a.roll_deg, density).c_str());
        } else if (o.json) {
          Json& out = w["rows"] = Json::array();
          for (const auto& st : rows) {
            Json row;
            write_fuel_state(row, st, range, density);
            out.push_back(std::move(row));
          }
        } else {
          append(out, "  %-14s %-14s %-10s %-14s %-14s\n", "level", "volume", "fraction",
                 "free surface", "wetted area");
          for (const auto& st : rows)
            append(out, "  %-14s %-14s %-10s %-14s %-14s\n", fmt(st.plane.level).c_str(),
                   fmt(st.volume).c_str(), fmt(st.fraction).c_str(), fmt(st.surface_area).c_str(),
                   fmt(st.wetted_area).c_str());
        }
        break;
      }
      case Options::Query::none:
        break;
    }
    if (grid) doc["attitudes"].push_back(std::move(attitude_fields));
    if (tty && grid && !o.json && (o.csv || o.query == Options::Query::table))
      std::fprintf(stderr, "\rpgamesh fuel: attitude %zu of %zu", ai + 1, atts.size());
  }
  if (tty && grid && !o.json && (o.csv || o.query == Options::Query::table))
    std::fprintf(stderr, "\n");
  if (o.json) out += json_text(doc) + "\n";
  std::fwrite(out.data(), 1, out.size(), stdout);
  if (!o.json)  // the JSON carries them in "warnings"
    for (const auto& warning : analysis.warnings)
      std::fprintf(stderr, "%s: warning: %s\n", o.file.c_str(), warning.c_str());
  return 0;
}

int run_fuel(const FuelArgs& args) {
  const Options o = resolve(args);
  try {
    return run(o);
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", o.file.c_str(), e.what());
  }
  return 1;
}

}  // namespace

void add_fuel_command(CLI::App& app) {
  CLI::App* sub = add_command(
      app, "fuel", "fuel gauging: volume, centre of mass, free surface at a level; inverse; tables",
      "Fuel in a closed tank mesh below the plane up.x = level (up normalised; the fuel is\n"
      "up.x <= level): volume, fraction, centre of mass, inertia, wetted area, free surface.\n"
      "Give one query: --level, --volume, --fraction, --table or --volumes.");
  sub->footer(
      "Tank frame: x forward, y left, z up. JSON fields: docs/json.md.\n"
      "Exit status: 0 on success, 1 for unreadable input, a mesh that is not a tank (without\n"
      "--force) or a level or volume outside the tank, 2 for bad usage.");
  auto a = std::make_shared<FuelArgs>();
  Options& o = a->o;
  add_file(*sub, o.file, "the tank mesh file");
  add_unit(*sub, o.unit,
           "the unit of a file that states none: mm, cm, m, in, ft, um\n"
           "(named in the output; a file's own unit differing from U is an error)");
  const std::string queries = "queries (one of)", attitude = "attitude (tank frame)",
                    mass = "mass (as in pgamesh props)", output = "output";
  add_number(*sub, "--level", a->level, "the fuel below level H")->type_name("H")->group(queries);
  add_number(*sub, "--volume", a->volume,
             "the level that holds volume V (Newton on dV/dlevel = surface area)")
      ->type_name("V")
      ->group(queries);
  add_number(*sub, "--fraction", a->fraction,
             "the level that holds the fraction F (0..1) of the tank")
      ->type_name("F")
      ->group(queries);
  a->table_given =
      add_count(*sub, "--table", a->table,
                "gauge table: N+1 levels from the lowest to the highest point", 1, 10'000'000)
          ->group(queries);
  a->volumes = add_numbers(*sub, "--volumes", o.volumes, "levels for a list of volumes")
                   ->type_name("V1,V2,...")
                   ->group(queries);
  a->up =
      add_vec3(*sub, "--up", o.up, "up vector of the level tank (default 0,0,1)")->group(attitude);
  a->pitch = add_numbers(*sub, "--pitch", o.pitch,
                         "pitch, positive nose up (a list makes a grid of attitudes)")
                 ->type_name("DEG[,...]")
                 ->group(attitude);
  a->roll =
      add_numbers(*sub, "--roll", o.roll, "roll, positive right side down (pitch first, then roll)")
          ->type_name("DEG[,...]")
          ->group(attitude);
  a->accel = add_vec3(*sub, "--accel", o.accel,
                      "apparent gravity in the tank frame (e.g. 0,0,-9.81 at rest):\n"
                      "up = -accel/|accel|; replaces --up, --pitch and --roll")
                 ->type_name("AX,AY,AZ")
                 ->group(attitude);
  add_positive_number(*sub, "--density", o.density,
                      "mass per unit volume (default 1: mass = volume)")
      ->type_name("RHO")
      ->group(mass);
  add_positive_number(*sub, "--mass", o.mass,
                      "mass of the full tank instead; the density is M / tank volume")
      ->type_name("M")
      ->group(mass);
  add_number(*sub, "--weld-tolerance", o.weld_tolerance,
             "gauge the mesh welded within T: vertices closer than T merge\n"
             "(a CAD export closed only up to rounding; default 0: as read)",
             0.0)
      ->type_name("T")
      ->group(output);
  sub->add_flag("--json", o.json, "one JSON object on stdout")->group(output);
  sub->add_flag("--csv", o.csv, "CSV with a commented header (tables and volume lists)")
      ->group(output);
  sub->add_flag("--force", o.force,
                "compute even when the mesh is open, inconsistently oriented\n"
                "or inside out (the same topology report as pgamesh check)")
      ->group(output);
  on_run(*sub, [a] { return run_fuel(*a); });
}

}  // namespace pgamesh::cli
