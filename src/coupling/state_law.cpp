#include "coupling/state_law.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "coupling/ave_time_reader.h"
#include "coupling/json_input.h"

namespace runin::coupling {

namespace {

constexpr const char *kFormat = "runin-state-law";
constexpr int kVersion = 1;

std::string format_number(double x) {
  std::ostringstream out;
  out.precision(6);
  out << x;
  return out.str();
}

bool may_be_negative(StateField field) { return field == StateField::Rsk; }

void check_grid(const std::vector<double> &grid, const char *name, bool starts_at_zero) {
  if (grid.size() < 2) throw std::invalid_argument(std::string(name) + ": at least 2 values are needed");
  for (std::size_t i = 0; i < grid.size(); ++i) {
    if (!std::isfinite(grid[i])) throw std::invalid_argument(std::string(name) + ": non-finite value");
    if (i > 0 && !(grid[i] > grid[i - 1]))
      throw std::invalid_argument(std::string(name) + ": values must increase strictly");
  }
  if (starts_at_zero && grid.front() != 0.0) throw std::invalid_argument(std::string(name) + ": must start at 0");
  if (!starts_at_zero && !(grid.front() > 0.0))
    throw std::invalid_argument(std::string(name) + ": values must be positive");
}

void check_table(const std::vector<std::vector<double>> &grid, const std::string &name, std::size_t np,
                 std::size_t nh, bool allow_negative) {
  if (grid.size() != np)
    throw std::invalid_argument(name + ": " + std::to_string(grid.size()) + " rows, expected one per pressure (" +
                                std::to_string(np) + ")");
  for (const auto &row : grid) {
    if (row.size() != nh)
      throw std::invalid_argument(name + ": a row has " + std::to_string(row.size()) +
                                  " values, expected one per worn depth (" + std::to_string(nh) + ")");
    for (double x : row) {
      if (!std::isfinite(x)) throw std::invalid_argument(name + ": non-finite value");
      if (!allow_negative && x < 0.0) throw std::invalid_argument(name + ": negative value " + format_number(x));
    }
  }
}

std::vector<double> read_vector(const nlohmann::json &node, const std::string &key) {
  if (!node.is_array()) throw std::invalid_argument(key + ": expected an array of numbers");
  std::vector<double> out;
  for (const auto &x : node) {
    if (!x.is_number()) throw std::invalid_argument(key + ": expected an array of numbers");
    out.push_back(x.get<double>());
  }
  return out;
}

std::vector<std::vector<double>> read_matrix(const nlohmann::json &node, const std::string &key) {
  if (!node.is_array()) throw std::invalid_argument(key + ": expected an array of rows");
  std::vector<std::vector<double>> out;
  for (const auto &row : node) out.push_back(read_vector(row, key));
  return out;
}

}  // namespace

const char *to_string(StateField field) {
  switch (field) {
    case StateField::MuBody: return "mu_body";
    case StateField::Rq: return "rq";
    case StateField::Rsk: return "rsk";
    case StateField::AreaFraction: return "area_fraction";
    case StateField::WearRate: return "wear_rate";
    case StateField::CounterfaceWearRate: return "counterface_wear_rate";
    case StateField::SlidingDistance: return "sliding_distance";
    case StateField::ContactFraction: return "contact_fraction";
  }
  return "?";
}

StateLaw::StateLaw(std::vector<double> pressure, std::vector<double> worn_depth,
                   std::array<StateFieldTable, state_field_count> fields, nlohmann::json metadata)
    : pressure_(std::move(pressure)), depth_(std::move(worn_depth)), fields_(std::move(fields)),
      metadata_(std::move(metadata)) {
  check_grid(pressure_, "pressure", false);
  check_grid(depth_, "worn_depth", true);
  // a cell far narrower than the axis makes the wear-rate slope (the continuum sub-step bound) near-infinite: a
  // depth repeated to 1e-15 stalled the tribometer in 1e8 sub-steps per call
  for (std::size_t j = 0; j + 1 < depth_.size(); ++j)
    if (depth_[j + 1] - depth_[j] < 1e-9 * depth_.back())
      throw std::invalid_argument("worn_depth: the cell from " + format_number(depth_[j]) + " to " +
                                  format_number(depth_[j + 1]) + " m is narrower than 1e-9 of the last depth (" +
                                  format_number(depth_.back()) + " m): merge the two depths");
  const std::size_t np = pressure_.size(), nh = depth_.size();
  for (std::size_t f = 0; f < state_field_count; ++f) {
    const auto field = static_cast<StateField>(f);
    const std::string name = to_string(field);
    const auto &t = fields_[f];
    const bool negative_ok = may_be_negative(field);
    if (optional_field(field) && t.mean.empty() && t.low.empty() && t.high.empty()) continue;
    check_table(t.mean, name + ".mean", np, nh, negative_ok);
    if (t.low.empty() != t.high.empty()) throw std::invalid_argument(name + ": low and high come together");
    if (!t.low.empty()) {
      check_table(t.low, name + ".low", np, nh, negative_ok);
      check_table(t.high, name + ".high", np, nh, negative_ok);
      for (std::size_t i = 0; i < np; ++i)
        for (std::size_t j = 0; j < nh; ++j)
          if (!(t.low[i][j] <= t.mean[i][j] && t.mean[i][j] <= t.high[i][j]))
            throw std::invalid_argument(name + ": low <= mean <= high fails at pressure " +
                                        format_number(pressure_[i]) + " Pa, worn depth " + format_number(depth_[j]) +
                                        " m");
    }
  }
  log_pressure_.resize(np);
  std::transform(pressure_.begin(), pressure_.end(), log_pressure_.begin(), [](double p) { return std::log(p); });
  if (!metadata_.is_object()) throw std::invalid_argument("metadata must be a JSON object");
}

std::optional<std::pair<std::string, std::string>> StateLaw::materials() const {
  const auto material = metadata_.find("material");
  if (material == metadata_.end() || !material->is_object()) return std::nullopt;
  const auto rough = material->find("rough"), counterface = material->find("counterface");
  if (rough == material->end() || counterface == material->end() || !rough->is_string() || !counterface->is_string())
    return std::nullopt;
  return std::make_pair(rough->get<std::string>(), counterface->get<std::string>());
}

bool StateLaw::has_band() const { return !fields_[0].low.empty(); }

StateLaw StateLaw::from_json(const nlohmann::json &document, const std::string &path) {
  try {
    if (!document.is_object()) throw std::invalid_argument("expected a JSON object");
    if (document.value("format", std::string()) != kFormat)
      throw std::invalid_argument(std::string("format: expected \"") + kFormat + "\"");
    if (!document.contains("version") || !document["version"].is_number_integer() ||
        document["version"].get<int>() != kVersion)
      throw std::invalid_argument("version: expected " + std::to_string(kVersion));
    for (const char *key : {"pressure", "worn_depth", "fields"})
      if (!document.contains(key)) throw std::invalid_argument(std::string("missing key \"") + key + "\"");
    auto pressure = read_vector(document["pressure"], "pressure");
    auto depth = read_vector(document["worn_depth"], "worn_depth");
    const auto &fields = document["fields"];
    if (!fields.is_object()) throw std::invalid_argument("fields: expected an object");
    std::array<StateFieldTable, state_field_count> tables;
    for (std::size_t f = 0; f < state_field_count; ++f) {
      const std::string name = to_string(static_cast<StateField>(f));
      if (!fields.contains(name)) {
        if (optional_field(static_cast<StateField>(f))) continue;
        throw std::invalid_argument("fields: missing \"" + name + "\"");
      }
      const auto &node = fields[name];
      if (!node.is_object() || !node.contains("mean"))
        throw std::invalid_argument("fields." + name + ": expected an object with \"mean\"");
      tables[f].mean = read_matrix(node["mean"], "fields." + name + ".mean");
      if (node.contains("low")) tables[f].low = read_matrix(node["low"], "fields." + name + ".low");
      if (node.contains("high")) tables[f].high = read_matrix(node["high"], "fields." + name + ".high");
    }
    nlohmann::json metadata = nlohmann::json::object();
    for (auto it = document.begin(); it != document.end(); ++it)
      if (it.key() != "format" && it.key() != "version" && it.key() != "pressure" && it.key() != "worn_depth" &&
          it.key() != "fields")
        metadata[it.key()] = it.value();
    return StateLaw(std::move(pressure), std::move(depth), std::move(tables), std::move(metadata));
  } catch (const std::invalid_argument &e) {
    throw InputFormatError(path + ": state law: " + e.what());
  } catch (const nlohmann::json::exception &e) {
    throw InputFormatError(path + ": state law: " + e.what());
  }
}

StateLaw StateLaw::read_file(const std::string &path) {
  std::ifstream in = open_input(path, "state law");
  std::ostringstream text;
  text << in.rdbuf();
  return from_json(parse_json_input(text.str(), path), path);
}

nlohmann::json StateLaw::to_json() const {
  nlohmann::json out = metadata_;
  out["format"] = kFormat;
  out["version"] = kVersion;
  out["pressure"] = pressure_;
  out["worn_depth"] = depth_;
  nlohmann::json fields = nlohmann::json::object();
  for (std::size_t f = 0; f < state_field_count; ++f) {
    if (fields_[f].mean.empty()) continue;  // an optional field the law lacks
    nlohmann::json node = {{"mean", fields_[f].mean}};
    if (!fields_[f].low.empty()) {
      node["low"] = fields_[f].low;
      node["high"] = fields_[f].high;
    }
    fields[to_string(static_cast<StateField>(f))] = std::move(node);
  }
  out["fields"] = std::move(fields);
  return out;
}

const char *to_string(OutOfRange policy) {
  switch (policy) {
    case OutOfRange::Error: return "error";
    case OutOfRange::Clamp: return "clamp";
    case OutOfRange::Archard: return "archard";
  }
  return "?";
}

bool StateLaw::proportional_to_pressure(StateField field) {
  return field == StateField::WearRate || field == StateField::CounterfaceWearRate ||
         field == StateField::AreaFraction || field == StateField::ContactFraction;
}

StateLaw::PressureSlice StateLaw::slice(double pressure, OutOfRange policy) const {
  if (!std::isfinite(pressure) || !(pressure > 0.0))
    throw std::out_of_range("state law: pressure " + format_number(pressure) + " Pa is not positive and finite");
  PressureSlice slice;
  double lp = std::log(pressure);
  if (pressure < pressure_.front() || pressure > pressure_.back()) {
    if (policy == OutOfRange::Error)
      throw std::out_of_range("state law: pressure " + format_number(pressure) + " Pa outside the law's range [" +
                              format_number(pressure_.front()) + ", " + format_number(pressure_.back()) + "] Pa");
    slice.clamped = pressure < pressure_.front() ? -1 : 1;
    if (policy == OutOfRange::Archard)
      slice.proportional_scale = pressure / (slice.clamped < 0 ? pressure_.front() : pressure_.back());
    lp = std::clamp(lp, log_pressure_.front(), log_pressure_.back());
  }
  const auto np = log_pressure_.size();
  slice.ip = static_cast<std::size_t>(std::upper_bound(log_pressure_.begin(), log_pressure_.end(), lp) -
                                      log_pressure_.begin());
  slice.ip = std::min(std::max<std::size_t>(slice.ip, 1), np - 1) - 1;
  slice.wp = (lp - log_pressure_[slice.ip]) / (log_pressure_[slice.ip + 1] - log_pressure_[slice.ip]);
  slice.wp = std::clamp(slice.wp, 0.0, 1.0);
  return slice;
}

StateLaw::Cell StateLaw::locate(double pressure, double worn_depth, OutOfRange policy, RangeUse *use) const {
  const PressureSlice s = slice(pressure, policy);
  return locate(s, worn_depth, use);
}

StateLaw::Cell StateLaw::locate(const PressureSlice &slice, double worn_depth, RangeUse *use) const {
  if (!std::isfinite(worn_depth))
    throw std::out_of_range("state law: worn depth " + format_number(worn_depth) + " m is not finite");
  if (use) {
    ++use->lookups;
    if (slice.clamped) ++(slice.clamped < 0 ? use->below_pressure : use->above_pressure);
  }
  Cell cell;
  cell.ip = slice.ip;
  cell.wp = slice.wp;
  cell.proportional_scale = slice.proportional_scale;
  double h = std::max(worn_depth, 0.0);
  if (h > depth_.back()) {
    if (use) ++use->beyond_depth;
    h = depth_.back();
  }
  const auto nh = depth_.size();
  cell.ih = static_cast<std::size_t>(std::upper_bound(depth_.begin(), depth_.end(), h) - depth_.begin());
  cell.ih = std::min(std::max<std::size_t>(cell.ih, 1), nh - 1) - 1;
  cell.wh = std::clamp((h - depth_[cell.ih]) / (depth_[cell.ih + 1] - depth_[cell.ih]), 0.0, 1.0);
  return cell;
}

double StateLaw::interpolate(const std::vector<std::vector<double>> &grid, const Cell &c) const {
  const double lower = (1.0 - c.wh) * grid[c.ip][c.ih] + c.wh * grid[c.ip][c.ih + 1];
  const double upper = (1.0 - c.wh) * grid[c.ip + 1][c.ih] + c.wh * grid[c.ip + 1][c.ih + 1];
  // Between pressures a power law when both sides are positive: the cell's wear rate goes as p (Archard) and
  // its adhesion friction as a power of p, which linear weights in ln p miss by ~10 % at a grid ratio of 2.4.
  // (at a grid pressure, wp = 0 or 1, no power is needed: nodes clamped to the grid's ends sit there)
  if (c.wp == 0.0) return lower;
  if (c.wp == 1.0) return upper;
  if (lower > 0.0 && upper > 0.0) return lower * std::pow(upper / lower, c.wp);
  return (1.0 - c.wp) * lower + c.wp * upper;
}

namespace {
void require(const StateLaw &law, StateField field) {
  if (!law.has(field))
    throw std::invalid_argument(std::string("state law: no field \"") + to_string(field) +
                                "\" (a law built before it: rebuild it with runin homogenise)");
}
}  // namespace

double StateLaw::value(StateField field, double pressure, double worn_depth, Band band, OutOfRange policy,
                       RangeUse *use) const {
  require(*this, field);
  const auto &t = table(field);
  const auto &grid = band == Band::Mean || t.low.empty() ? t.mean : band == Band::Low ? t.low : t.high;
  const Cell c = locate(pressure, worn_depth, policy, use);
  return interpolate(grid, c) * (proportional_to_pressure(field) ? c.proportional_scale : 1.0);
}

double StateLaw::value(StateField field, const PressureSlice &slice, double worn_depth, RangeUse *use) const {
  require(*this, field);
  const Cell c = locate(slice, worn_depth, use);
  return interpolate(table(field).mean, c) * (proportional_to_pressure(field) ? c.proportional_scale : 1.0);
}

void StateLaw::wear_rates(const PressureSlice &slice, double worn_depth, RangeUse *use, double &wear_rate,
                          double &counterface_wear_rate) const {
  const Cell c = locate(slice, worn_depth, use);
  wear_rate = interpolate(table(StateField::WearRate).mean, c) * c.proportional_scale;
  counterface_wear_rate = interpolate(table(StateField::CounterfaceWearRate).mean, c) * c.proportional_scale;
}

StateLawValues StateLaw::values(double pressure, double worn_depth, OutOfRange policy, RangeUse *use) const {
  const Cell c = locate(pressure, worn_depth, policy, use);
  StateLawValues v;
  v.mu_body = interpolate(table(StateField::MuBody).mean, c);
  v.rq = interpolate(table(StateField::Rq).mean, c);
  v.rsk = interpolate(table(StateField::Rsk).mean, c);
  v.area_fraction = interpolate(table(StateField::AreaFraction).mean, c) * c.proportional_scale;
  v.wear_rate = interpolate(table(StateField::WearRate).mean, c) * c.proportional_scale;
  v.counterface_wear_rate = interpolate(table(StateField::CounterfaceWearRate).mean, c) * c.proportional_scale;
  if (has(StateField::ContactFraction))
    v.contact_fraction = interpolate(table(StateField::ContactFraction).mean, c) * c.proportional_scale;
  return v;
}

}  // namespace runin::coupling
