#include "fuel_routes.hpp"

#include <charconv>
#include <cstdio>
#include <numbers>
#include <stdexcept>

#include "fuel_json.hpp"
#include "fuel_model.hpp"
#include "pgamesh/tank/attitude.hpp"
#include "pgamesh/tank/fuel_sweep.hpp"
#include "pgamesh/tank/inverse_level.hpp"
#include "responses.hpp"

namespace pgamesh::viewer {

namespace {

constexpr int kMaxTableSteps = 1000;

struct Attitude {
  double pitch_deg = 0, roll_deg = 0;
  Vec3d up{0, 0, 1};
};

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.9g", v);
  return buf;
}

// pitch and roll in degrees (default 0) on the level tank's up +z (tank frame: x forward, y left,
// z up; tank/attitude.hpp). False after answering 400.
bool read_attitude(const httplib::Request& req, httplib::Response& res, Attitude& a) {
  for (auto [name, value] : {std::pair{"pitch", &a.pitch_deg}, std::pair{"roll", &a.roll_deg}}) {
    if (!req.has_param(name)) continue;
    if (!parse_number(req.get_param_value(name), *value) || *value < -180 || *value > 180) {
      send_error(res, 400, std::string(name) + " must be a number of degrees in [-180, 180]");
      return false;
    }
  }
  constexpr double deg = std::numbers::pi / 180;
  a.up = tank::up_from_attitude({0, 0, 1}, a.pitch_deg * deg, a.roll_deg * deg);
  return true;
}

// The gaugeable tank of the route's mesh, or nullptr after answering 404/422.
std::shared_ptr<const FuelModel> read_tank(MeshStore& store, const httplib::Request& req,
                                           httplib::Response& res) {
  const auto m = find_mesh(store, req.matches[1], res);
  if (!m) return nullptr;
  auto model = fuel_model(*m);
  if (!model->problem.empty()) {
    send_error(res, 422, model->problem);
    return nullptr;
  }
  return model;
}

void write_header(cli::Json& w, const FuelModel& model, const Attitude& a,
                  const tank::LevelRange& range) {
  w["up"] = cli::json_vec3(a.up);
  w["pitch_deg"] = cli::json_number(a.pitch_deg);
  w["roll_deg"] = cli::json_number(a.roll_deg);
  w["tank_volume"] = cli::json_number(model.tank.volume);
  w["lowest"] = cli::json_number(range.lowest);
  w["highest"] = cli::json_number(range.highest);
}

void fuel_query(MeshStore& store, const httplib::Request& req, httplib::Response& res) {
  Attitude a;
  if (!read_attitude(req, res, a)) return;
  const bool by_level = req.has_param("level"), by_volume = req.has_param("volume");
  double target = 0;
  if (by_level == by_volume) return send_error(res, 400, "give exactly one of level= and volume=");
  if (!parse_number(req.get_param_value(by_level ? "level" : "volume"), target))
    return send_error(res, 400, std::string(by_level ? "level" : "volume") + " must be a number");
  const auto model = read_tank(store, req, res);
  if (!model) return;
  const tank::LevelRange range = model->index->range(a.up);
  cli::Json w;
  write_header(w, *model, a, range);
  if (by_level) {
    // No silent clamping: outside the tank is an answer of its own (as `pgamesh fuel` says).
    if (target < range.lowest || target > range.highest)
      return send_error(res, 422,
                        "level " + fmt(target) + " is " +
                            (target < range.lowest ? "below" : "above") + " the tank (from " +
                            fmt(range.lowest) + " to " + fmt(range.highest) + " along up)");
    cli::write_fuel_state(w, model->index->query(tank::FuelPlane{a.up, target}), range);
  } else {
    tank::LevelSolution s;
    try {
      s = tank::level_for_volume(*model->index, a.up, target);
    } catch (const std::domain_error& e) {
      return send_error(res, 422, std::string("volume ") + fmt(target) + ": " + e.what());
    }
    w["target_volume"] = cli::json_number(target);
    w["iterations"] = s.iterations;
    cli::write_fuel_state(w, model->index->query(tank::FuelPlane{a.up, s.level}), range);
  }
  send_raw_json(res, cli::json_text(w));
}

void fuel_table(MeshStore& store, const httplib::Request& req, httplib::Response& res) {
  Attitude a;
  if (!read_attitude(req, res, a)) return;
  int n = 64;
  if (req.has_param("n")) {
    const std::string text = req.get_param_value("n");
    const auto [p, ec] = std::from_chars(text.data(), text.data() + text.size(), n);
    if (ec != std::errc() || p != text.data() + text.size() || n < 1 || n > kMaxTableSteps)
      return send_error(res, 400,
                        "n must be an integer from 1 to " + std::to_string(kMaxTableSteps));
  }
  const auto model = read_tank(store, req, res);
  if (!model) return;
  const tank::LevelRange range = model->index->range(a.up);
  const auto rows = tank::fuel_sweep(model->tank, a.up, tank::even_levels(range, n));
  cli::Json w;
  write_header(w, *model, a, range);
  cli::Json& out = w["rows"] = cli::Json::array();
  for (const tank::FuelState& st : rows) {
    cli::Json row;
    cli::write_fuel_state(row, st, range);
    out.push_back(std::move(row));
  }
  send_raw_json(res, cli::json_text(w));
}

}  // namespace

void add_fuel_routes(httplib::Server& svr, MeshStore& store) {
  svr.Get(R"(/api/mesh/([fu][0-9]{1,18})/fuel)",
          [&store](const httplib::Request& req, httplib::Response& res) {
            fuel_query(store, req, res);
          });
  svr.Get(R"(/api/mesh/([fu][0-9]{1,18})/fuel/table)",
          [&store](const httplib::Request& req, httplib::Response& res) {
            fuel_table(store, req, res);
          });
}

}  // namespace pgamesh::viewer
