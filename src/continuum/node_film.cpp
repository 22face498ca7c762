#include "continuum/node_film.h"

#include "tribo/contact_model.h"
#include "tribo/number_format.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace runin::continuum {
namespace {
using tribo::format_g;
void require(bool ok, const std::string &key, const std::string &what, double got) {
  if (!ok) throw std::invalid_argument(key + ": " + what + ", got " + format_g(got));
}
}  // namespace

void FilmSettings::validate() const {
  require(coverage >= 0.0 && coverage <= 1.0, "film.coverage", "the initial film coverage must be in [0, 1]", coverage);
  require(f_film >= 0.0 && f_film < 1.0, "film.f_film",
          "the film's interface coefficient must be in [0, 1) (at 1 a junction grows without bound)", f_film);
  require(f_base > 0.0 && f_base < 1.0, "film.f_base", "the bare interface coefficient must be in (0, 1)", f_base);
  require(alpha > 0.0 && std::isfinite(alpha), "film.alpha", "the junction growth constant must be > 0 and finite",
          alpha);
  require(removal_distance >= 0.0 && std::isfinite(removal_distance), "film.removal_distance",
          "the film removal distance must be >= 0 m (0: no removal)", removal_distance);
  require(growth_rate >= 0.0 && std::isfinite(growth_rate), "film.growth_rate",
          "the film growth rate must be >= 0 1/s (0: no growth)", growth_rate);
  if (!counterface) return;
  const auto &c = *counterface;
  require(c.coverage >= 0.0 && c.coverage <= 1.0, "film.counterface_coverage",
          "the counterface's initial film coverage must be in [0, 1]", c.coverage);
  require(c.removal_distance >= 0.0 && std::isfinite(c.removal_distance), "film.counterface_removal_distance",
          "the counterface film's removal distance must be >= 0 m (0: no removal)", c.removal_distance);
  require(c.growth_rate >= 0.0 && std::isfinite(c.growth_rate), "film.counterface_growth_rate",
          "the counterface film's growth rate must be >= 0 1/s (0: no growth)", c.growth_rate);
}

NodeFilm::NodeFilm(const FilmSettings &settings, std::size_t nodes)
    : s_((settings.validate(), settings)),
      kinetics_(settings.removal_distance, settings.growth_rate),
      counterface_kinetics_(settings.counterface ? settings.counterface->removal_distance : 0.0,
                            settings.counterface ? settings.counterface->growth_rate : 0.0),
      theta_(nodes, settings.coverage),
      theta_cf_(settings.counterface ? nodes : 0, settings.counterface ? settings.counterface->coverage : 0.0),
      tabor_base_(tabor(settings.f_base)) {}

double NodeFilm::contact_coverage(std::size_t node) const {
  return theta_cf_.empty() ? theta_[node] : 0.5 * (theta_[node] + theta_cf_[node]);
}

double NodeFilm::tabor(double f) const { return tribo::JunctionFrictionModel::tabor_sliding_ratio(f, s_.alpha); }

double NodeFilm::friction_factor(std::size_t node) const {
  return tabor(tribo::FilmKinetics::interpolate(contact_coverage(node), s_.f_base, s_.f_film)) / tabor_base_;
}

void NodeFilm::advance(const std::vector<double> &contact_fraction, double ds, double dt, double counterface_duty) {
  if (contact_fraction.size() != theta_.size()) throw std::invalid_argument("node film: size mismatch");
  if (!(ds >= 0.0 && dt >= 0.0)) throw std::invalid_argument("node film: ds and dt must be >= 0");
  if (!(counterface_duty > 0.0 && counterface_duty <= 1.0))
    throw std::invalid_argument("node film: the counterface duty must be in (0, 1]");
  const double growth = kinetics_.growth(dt), growth_cf = counterface_kinetics_.growth(dt);
  for (std::size_t i = 0; i < theta_.size(); ++i) {
    theta_[i] = tribo::FilmKinetics::advance(theta_[i], kinetics_.removal(contact_fraction[i] * ds), growth);
    if (!theta_cf_.empty())
      theta_cf_[i] = tribo::FilmKinetics::advance(
          theta_cf_[i], counterface_kinetics_.removal(contact_fraction[i] * counterface_duty * ds), growth_cf);
  }
}

double NodeFilm::mean_coverage(const std::vector<double> &weight) const {
  double sum = 0.0, total = 0.0, plain = 0.0;
  for (std::size_t i = 0; i < theta_.size(); ++i) {
    sum += contact_coverage(i) * weight[i];
    total += weight[i];
    plain += contact_coverage(i);
  }
  if (total > 0.0) return sum / total;
  return theta_.empty() ? 0.0 : plain / static_cast<double>(theta_.size());
}

FilmStepBound film_step_bound(const FilmSettings &s, double ds, double dt, double tolerance) {
  const CounterfaceFilm cf = s.counterface.value_or(CounterfaceFilm{});
  const std::pair<FilmInput, double> exposure[] = {
      {FilmInput::RemovalDistance, s.removal_distance > 0.0 ? ds / s.removal_distance : 0.0},
      {FilmInput::GrowthRate, s.growth_rate * dt},
      {FilmInput::CounterfaceRemovalDistance, cf.removal_distance > 0.0 ? ds / cf.removal_distance : 0.0},
      {FilmInput::CounterfaceGrowthRate, cf.growth_rate * dt}};
  double total = 0.0;
  for (const auto &e : exposure) total += e.second;
  // d ln T / df of T(f) = f / sqrt(alpha (1 - f^2)), independent of alpha
  const auto slope = [](double f) { return 1.0 / f + f / (1.0 - f * f); };
  const double f_film = std::fabs(s.f_film);  // -0 as 0: slope +inf
  const double lo = std::min(f_film, s.f_base), hi = std::max(f_film, s.f_base);
  FilmStepBound bound;
  bound.change = std::min(1.0, total) * (hi - lo) * std::max(slope(lo), slope(hi));
  if (!(bound.change > tolerance)) return bound;
  const auto fastest = std::max_element(std::begin(exposure), std::end(exposure),
                                        [](const auto &a, const auto &b) { return a.second < b.second; });
  bound.input = total > tolerance ? fastest->first : FilmInput::FFilm;
  return bound;
}

}  // namespace runin::continuum
