// `pgamesh fuel FILE --up X,Y,Z (--level H | --volume V | --fraction F | --table N |
// --volumes V1,V2,...) [--pitch DEG[,DEG...]] [--roll DEG[,DEG...]] [--accel AX,AY,AZ]
// [--density RHO | --mass M] [--json | --csv] [--force]`: fuel gauging of a closed tank (DESIGN.md
// §5, docs/fuel.md).
#include <unistd.h>

#include <charconv>
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
#include "json_writer.hpp"
#include "pgamesh/core/input_error.hpp"
#include "pgamesh/io/read_mesh.hpp"
#include "pgamesh/mesh/topology/topology.hpp"
#include "pgamesh/tank/attitude.hpp"
#include "pgamesh/tank/fuel_index.hpp"
#include "pgamesh/tank/fuel_sweep.hpp"
#include "pgamesh/tank/inverse_level.hpp"

namespace pgamesh::cli {

namespace {

void print_fuel_help(std::FILE* out) {
  std::fprintf(
      out,
      "usage: pgamesh fuel FILE [--up X,Y,Z] (--level H | --volume V | --fraction F |\n"
      "                          --table N | --volumes V1,V2,...) [options]\n"
      "\n"
      "Fuel in a closed tank mesh below the plane up.x = level (up normalised; the fuel is\n"
      "up.x <= level): volume, fraction, centre of mass, inertia, wetted area, free surface.\n"
      "\n"
      "queries (one of):\n"
      "  --level H          the fuel below level H\n"
      "  --volume V         the level that holds volume V (Newton on dV/dlevel = surface area)\n"
      "  --fraction F       the level that holds the fraction F (0..1) of the tank\n"
      "  --table N          gauge table: N+1 levels from the lowest to the highest point\n"
      "  --volumes V1,...   levels for a list of volumes\n"
      "\n"
      "attitude (tank frame: x forward, y left, z up):\n"
      "  --up X,Y,Z         up vector of the level tank (default 0,0,1)\n"
      "  --pitch DEG[,...]  pitch, positive nose up (a list makes a grid of attitudes)\n"
      "  --roll DEG[,...]   roll, positive right side down (pitch first, then roll)\n"
      "  --accel AX,AY,AZ   apparent gravity in the tank frame (e.g. 0,0,-9.81 at rest):\n"
      "                     up = -accel/|accel|; replaces --up, --pitch and --roll\n"
      "\n"
      "mass (as in pgamesh props):\n"
      "  --density RHO      mass per unit volume (default 1: mass = volume)\n"
      "  --mass M           mass of the full tank instead; the density is M / tank volume\n"
      "\n"
      "output:\n"
      "  --json             one JSON object on stdout\n"
      "  --csv              CSV with a commented header (tables and volume lists)\n"
      "  --force            compute even when the mesh is open, inconsistently oriented\n"
      "                     or inside out (the same topology report as pgamesh check)\n");
}

struct Options {
  std::string file;
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
  bool json = false, csv = false, force = false;
};

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

double parse_number(std::string_view option, std::string_view text) {
  double v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v))
    throw UsageError(std::string(option) + ": '" + std::string(text) + "' is not a finite number");
  return v;
}

std::vector<double> parse_list(std::string_view option, std::string_view text) {
  std::vector<double> out;
  std::size_t start = 0;
  for (;;) {
    const std::size_t comma = text.find(',', start);
    out.push_back(parse_number(option, text.substr(start, comma - start)));
    if (comma == std::string_view::npos) break;
    start = comma + 1;
  }
  return out;
}

Vec3d parse_vec(std::string_view option, std::string_view text) {
  const auto v = parse_list(option, text);
  if (v.size() != 3) throw UsageError(std::string(option) + " needs three numbers X,Y,Z");
  return {v[0], v[1], v[2]};
}

Options parse(int argc, char** argv) {
  Options o;
  auto set_query = [&](Options::Query q) {
    if (o.query != Options::Query::none)
      throw UsageError("give only one of --level, --volume, --fraction, --table, --volumes");
    o.query = q;
  };
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    auto value = [&]() -> std::string_view {
      if (i + 1 >= argc) throw UsageError(std::string(arg) + " needs a value");
      return argv[++i];
    };
    if (arg == "--up") {
      o.up = parse_vec(arg, value());
      o.up_given = true;
    } else if (arg == "--pitch") {
      o.pitch = parse_list(arg, value());
      o.attitude = true;
    } else if (arg == "--roll") {
      o.roll = parse_list(arg, value());
      o.attitude = true;
    } else if (arg == "--accel") {
      o.accel = parse_vec(arg, value());
      o.accel_given = true;
    } else if (arg == "--level") {
      set_query(Options::Query::level);
      o.value = parse_number(arg, value());
    } else if (arg == "--volume") {
      set_query(Options::Query::volume);
      o.value = parse_number(arg, value());
    } else if (arg == "--fraction") {
      set_query(Options::Query::fraction);
      o.value = parse_number(arg, value());
    } else if (arg == "--table") {
      set_query(Options::Query::table);
      const double n = parse_number(arg, value());
      if (n < 1 || n > 10'000'000 || n != std::floor(n))
        throw UsageError("--table N needs a whole number of steps from 1 to 10000000");
      o.table = static_cast<int>(n);
    } else if (arg == "--volumes") {
      set_query(Options::Query::volumes);
      o.volumes = parse_list(arg, value());
    } else if (arg == "--density") {
      o.density = parse_number(arg, value());
    } else if (arg == "--mass") {
      o.mass = parse_number(arg, value());
    } else if (arg == "--json") {
      o.json = true;
    } else if (arg == "--csv") {
      o.csv = true;
    } else if (arg == "--force") {
      o.force = true;
    } else if (!arg.empty() && arg[0] == '-' && arg != "-") {
      throw UsageError("unknown option '" + std::string(arg) + "'");
    } else if (o.file.empty()) {
      o.file = arg;
    } else {
      throw UsageError("more than one FILE given");
    }
  }
  if (o.file.empty()) throw UsageError("no FILE given");
  if (o.query == Options::Query::none)
    throw UsageError("give one of --level, --volume, --fraction, --table, --volumes");
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
  bool forced = false;  // unfit, computed anyway (--force)
};

void write_header(JsonWriter& w, const Options& o, const tank::Tank& t, const TankCheck& check,
                  double density) {
  w.string("file", o.file);
  w.integer("triangles", t.triangles.size());
  w.number("tank_volume", t.volume);
  w.number("density", density);
  w.number("tank_mass", density * t.volume);
  const TopologyReport& r = check.topology;
  w.begin_object("topology");
  w.boolean("closed", r.closed);
  w.boolean("orientation_consistent", r.orientation_consistent);
  w.integer("boundary_edges", r.boundary_edges);
  w.integer("nonmanifold_edges", r.nonmanifold_edges);
  w.integer("inconsistent_edges", r.inconsistent_edges);
  w.number("gap_area", r.gap_area);
  w.boolean("volume_valid", r.volume_valid);
  w.begin_array("notes");
  for (const auto& note : r.notes) w.string(note);
  w.end_array();
  w.end_object();
  w.boolean("forced", check.forced);
  write_fuel_conventions(w);
}

void write_attitude(JsonWriter& w, const Options& o, const Attitude& a) {
  w.vec3("up", a.up);
  if (o.attitude) {
    w.number("pitch_deg", a.pitch_deg);
    w.number("roll_deg", a.roll_deg);
  }
}

void print_state(const tank::FuelState& st, const tank::LevelRange& range, double density) {
  std::printf("  level           %s (tank from %s to %s along up)\n", fmt(st.plane.level).c_str(),
              fmt(range.lowest).c_str(), fmt(range.highest).c_str());
  std::printf("  volume          %s (fraction %s), ullage %s\n", fmt(st.volume).c_str(),
              fmt(st.fraction).c_str(), fmt(st.ullage_volume).c_str());
  if (density != 1)
    std::printf("  mass            %s (density %s)\n", fmt(density * st.volume).c_str(),
                fmt(density).c_str());
  if (st.has_center)
    std::printf("  centre of mass  %s %s %s\n", fmt(st.center_of_mass.x).c_str(),
                fmt(st.center_of_mass.y).c_str(), fmt(st.center_of_mass.z).c_str());
  std::printf("  wetted area     %s\n", fmt(st.wetted_area).c_str());
  std::printf("  free surface    %s, moments of area: transverse %s, longitudinal %s\n",
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

int run(const Options& o) {
  const Mesh mesh = read_mesh(o.file);
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
  JsonWriter w;
  w.begin_object();
  write_header(w, o, t, check, density);
  if (grid) w.begin_array("attitudes");
  if (o.csv) {
    std::printf(
        "# pgamesh fuel: %s\n# fuel is up.x <= level (up a unit vector, tank frame x "
        "forward, y left, z up); ullage_length = highest point - level\n"
        "# units: lengths in the mesh unit L, areas L^2, volumes L^3, moments of area "
        "L^4; mass = density x volume in the unit of the density times L^3\n"
        "# density %.17g\n# tank_volume %.17g\n",
        o.file.c_str(), density, t.volume);
  }
  const bool csv_attitude = o.attitude || grid;
  std::unique_ptr<tank::FuelIndex> index;
  for (std::size_t ai = 0; ai < atts.size(); ++ai) {
    const Attitude& a = atts[ai];
    const tank::LevelRange range = tank::level_range(t, a.up);
    if (grid) w.begin_object();
    if (o.csv && (ai == 0 || grid))
      std::printf(
          "# up %.17g,%.17g,%.17g%s\n", a.up.x, a.up.y, a.up.z,
          o.attitude ? (" pitch " + fmt(a.pitch_deg) + " roll " + fmt(a.roll_deg)).c_str() : "");
    write_attitude(w, o, a);
    if (!o.json && !o.csv)
      std::printf(
          "%s: up %s %s %s%s\n", o.file.c_str(), fmt(a.up.x).c_str(), fmt(a.up.y).c_str(),
          fmt(a.up.z).c_str(),
          o.attitude
              ? (" (pitch " + fmt(a.pitch_deg) + " deg, roll " + fmt(a.roll_deg) + " deg)").c_str()
              : "");
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
          if (ai == 0) std::printf("%s\n", fuel_csv_columns(csv_attitude).c_str());
          std::printf(
              "%s\n",
              fuel_csv_row(st, range, csv_attitude, a.pitch_deg, a.roll_deg, density).c_str());
        } else if (o.json) {
          write_fuel_state(w, st, range, density);
        } else {
          print_state(st, range, density);
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
        if (o.query == Options::Query::volumes) w.begin_array("rows");
        if (o.csv && (ai == 0))
          std::printf("target_volume,iterations,%s\n", fuel_csv_columns(csv_attitude).c_str());
        for (double v : targets) {
          const tank::LevelSolution s = tank::level_for_volume(*index, a.up, v);
          const tank::FuelState st = index->query(tank::FuelPlane{a.up, s.level});
          if (o.csv) {
            std::printf(
                "%.17g,%d,%s\n", v, s.iterations,
                fuel_csv_row(st, range, csv_attitude, a.pitch_deg, a.roll_deg, density).c_str());
          } else if (o.json) {
            if (o.query == Options::Query::volumes) w.begin_object();
            w.number("target_volume", v);
            w.integer("iterations", static_cast<unsigned long long>(s.iterations));
            write_fuel_state(w, st, range, density);
            if (o.query == Options::Query::volumes) w.end_object();
          } else {
            std::printf("  target volume   %s (%d fuel queries)\n", fmt(v).c_str(), s.iterations);
            print_state(st, range, density);
          }
        }
        if (o.query == Options::Query::volumes) w.end_array();
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
          if (ai == 0) std::printf("%s\n", fuel_csv_columns(csv_attitude).c_str());
          for (const auto& st : rows)
            std::printf(
                "%s\n",
                fuel_csv_row(st, range, csv_attitude, a.pitch_deg, a.roll_deg, density).c_str());
        } else if (o.json) {
          w.begin_array("rows");
          for (const auto& st : rows) {
            w.begin_object();
            write_fuel_state(w, st, range, density);
            w.end_object();
          }
          w.end_array();
        } else {
          std::printf("  %-14s %-14s %-10s %-14s %-14s\n", "level", "volume", "fraction",
                      "free surface", "wetted area");
          for (const auto& st : rows)
            std::printf("  %-14s %-14s %-10s %-14s %-14s\n", fmt(st.plane.level).c_str(),
                        fmt(st.volume).c_str(), fmt(st.fraction).c_str(),
                        fmt(st.surface_area).c_str(), fmt(st.wetted_area).c_str());
        }
        break;
      }
      case Options::Query::none:
        break;
    }
    if (grid) w.end_object();
    if (tty && grid && !o.json && (o.csv || o.query == Options::Query::table))
      std::fprintf(stderr, "\rpgamesh fuel: attitude %zu of %zu", ai + 1, atts.size());
  }
  if (tty && grid && !o.json && (o.csv || o.query == Options::Query::table))
    std::fprintf(stderr, "\n");
  if (grid) w.end_array();
  w.end_object();
  if (o.json) std::printf("%s\n", w.str().c_str());
  return 0;
}

int run_fuel(int argc, char** argv) {
  for (int i = 1; i < argc; ++i)
    if (std::string_view(argv[i]) == "--help" || std::string_view(argv[i]) == "-h") {
      print_fuel_help(stdout);
      return 0;
    }
  Options o;
  try {
    o = parse(argc, argv);
  } catch (const UsageError& e) {
    std::fprintf(stderr, "pgamesh fuel: %s\n(see pgamesh fuel --help)\n", e.what());
    return 2;
  }
  try {
    return run(o);
  } catch (const InputError& e) {
    std::fprintf(stderr, "%s\n", e.what());
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s: %s\n", o.file.c_str(), e.what());
  }
  return 1;
}

const RegisterCommand registered{
    {"fuel", "fuel gauging: volume, centre of mass, free surface at a level; inverse; tables",
     run_fuel, 30}};

}  // namespace

}  // namespace pgamesh::cli
