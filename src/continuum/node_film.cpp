#include "continuum/node_film.h"

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

namespace runin::continuum {
namespace {
std::string g(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}
void require(bool ok, const std::string &key, const std::string &what, double got) {
  if (!ok) throw std::invalid_argument(key + ": " + what + ", got " + g(got));
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
}

NodeFilm::NodeFilm(const FilmSettings &settings, std::size_t nodes)
    : s_((settings.validate(), settings)),
      kinetics_(settings.removal_distance, settings.growth_rate),
      theta_(nodes, settings.coverage),
      tabor_base_(tabor(settings.f_base)) {}

double NodeFilm::tabor(double f) const { return f / std::sqrt(s_.alpha * (1.0 - f * f)); }

double NodeFilm::friction_factor(std::size_t node) const {
  return tabor(tribo::FilmKinetics::interpolate(theta_[node], s_.f_base, s_.f_film)) / tabor_base_;
}

void NodeFilm::advance(const std::vector<double> &contact_fraction, double ds, double dt) {
  if (contact_fraction.size() != theta_.size()) throw std::invalid_argument("node film: size mismatch");
  if (!(ds >= 0.0 && dt >= 0.0)) throw std::invalid_argument("node film: ds and dt must be >= 0");
  const double growth = kinetics_.growth(dt);
  for (std::size_t i = 0; i < theta_.size(); ++i)
    theta_[i] = tribo::FilmKinetics::advance(theta_[i], kinetics_.removal(contact_fraction[i] * ds), growth);
}

double NodeFilm::mean_coverage(const std::vector<double> &weight) const {
  double sum = 0.0, total = 0.0, plain = 0.0;
  for (std::size_t i = 0; i < theta_.size(); ++i) {
    sum += theta_[i] * weight[i];
    total += weight[i];
    plain += theta_[i];
  }
  if (total > 0.0) return sum / total;
  return theta_.empty() ? 0.0 : plain / static_cast<double>(theta_.size());
}

}  // namespace runin::continuum
