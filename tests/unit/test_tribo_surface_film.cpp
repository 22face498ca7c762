// Surface-film kinetics (src/tribo/surface_film.h) and the friction sub-model 'junction/film'
// (src/tribo/contact_model.h): the coverage against the closed forms of its linear law, with growth off
// (theta0 exp(-s / s_r)), removal off (1 - (1 - theta0) exp(-k_g t)) and both (the steady state
// theta* = k_g / (k_g + v / s_r) and the approach to it); the friction of a plastic junction at coverage 1, 0 and in
// between against Tabor's closed form with the interpolated f; the coefficient checks; mixing and the restart record.
#include "tribo/contact_model.h"
#include "tribo/surface_film.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace tribo = runin::tribo;
using tribo::FilmKinetics;
using tribo::SubModelKind;

namespace {

constexpr int kElasticPlastic = 1, kJunctionFilm = 4;
static_assert(std::is_same_v<std::tuple_element_t<kJunctionFilm, tribo::FrictionModels>,
                             tribo::JunctionFilmFrictionModel>,
              "the tests dispatch on the film model's registry index");

template <class F> std::string message_of(const F &make)
{
  try {
    make();
  } catch (const tribo::InvalidCoefficient &e) {
    return e.what();
  }
  return "";
}

// Uneven steps (slip and dt vary), as the hosts' steps do: the closed forms must hold whatever the steps.
double step_fraction(int k) { return 0.5 + 0.5 * std::sin(0.7 * k) * std::sin(0.7 * k); }

tribo::ContactModelChoice film_choice()
{
  tribo::ContactModelChoice c;
  c.index[static_cast<int>(SubModelKind::normal)] = kElasticPlastic;
  c.index[static_cast<int>(SubModelKind::friction)] = kJunctionFilm;
  return c;
}

tribo::ContactParameters steel(double f_clean, double f_film, double s_r = 0.0, double k_g = 0.0)
{
  tribo::ContactParameters p;
  p.effective_modulus = 1.092e11;
  p.effective_shear_modulus = 4.3e10;
  p.restitution = 1.0;
  p.hardness_i = 1.19e9;
  p.hardness_j = 6.0e9;
  p.yield_strength = 350e6;
  p.poisson_ratio = 0.29;
  p.interface_coefficient = f_clean;
  p.film_interface_coefficient = f_film;
  p.film_removal_distance = s_r;
  p.film_growth_rate = k_g;
  return p;
}

double tabor(double f, double alpha) { return f / std::sqrt(alpha * (1.0 - f * f)); }

}    // namespace

// Growth off: every slip increment ds strips theta ds / s_r, so after a slip s the coverage is theta0 exp(-s / s_r)
// (to round-off, for any split of s into steps).
TEST(SurfaceFilm, GrowthOffDecaysByTheRemovalClosedForm)
{
  const FilmKinetics film(2e-7, 0.0);
  double theta = 0.9, slid = 0.0;
  for (int k = 0; k < 5000; ++k) {
    const double ds = 1e-10 * step_fraction(k);
    theta = FilmKinetics::advance(theta, film.removal(ds), film.growth(1e-8));
    slid += ds;
    ASSERT_NEAR(theta, 0.9 * std::exp(-slid / 2e-7), 1e-13 * 0.9 * std::exp(-slid / 2e-7)) << k;
  }
  EXPECT_LT(theta, 0.9 * 0.2);    // about two removal distances slid
}

// Removal off: the bare fraction decays at the growth rate, theta = 1 - (1 - theta0) exp(-k_g t).
TEST(SurfaceFilm, RemovalOffGrowsByTheGrowthClosedForm)
{
  const FilmKinetics film(0.0, 2e3);
  double theta = 0.1, t = 0.0;
  for (int k = 0; k < 5000; ++k) {
    const double dt = 2e-7 * step_fraction(k);
    theta = FilmKinetics::advance(theta, film.removal(1e-6), film.growth(dt));
    t += dt;
    const double want = 1.0 - 0.9 * std::exp(-2e3 * t);
    ASSERT_NEAR(theta, want, 1e-13) << k;
  }
  EXPECT_GT(theta, 0.75);    // about 1.5 growth times
}

// Both: at a steady slip rate v the coverage relaxes to theta* = k_g / (k_g + v / s_r) at the rate k_g + v / s_r,
// from above (a covered start) and from below (a clean start); the steady state is the same from either side.
TEST(SurfaceFilm, SteadyStateOfRemovalAndGrowth)
{
  const double s_r = 1e-6, k_g = 5e4, v = 0.1, dt = 1e-8;
  const FilmKinetics film(s_r, k_g);
  const double steady = k_g / (k_g + v / s_r), rate = k_g + v / s_r;
  EXPECT_NEAR(film.steady_state(v), steady, 1e-15);
  EXPECT_NEAR(steady, 1.0 / 3.0, 1e-15);
  for (double theta0 : {1.0, 0.0}) {
    double theta = theta0;
    for (int k = 1; k <= 20000; ++k) {
      theta = FilmKinetics::advance(theta, film.removal(v * dt), film.growth(dt));
      const double want = steady + (theta0 - steady) * std::exp(-rate * k * dt);
      ASSERT_NEAR(theta, want, 1e-12) << theta0 << " " << k;
    }
    EXPECT_NEAR(theta, steady, 1e-12);    // 30 relaxation times
  }
  EXPECT_EQ(FilmKinetics(0.0, 0.0).steady_state(v), 1.0);    // nothing changes the film
  EXPECT_EQ(FilmKinetics(s_r, 0.0).steady_state(v), 0.0);    // worn off for good
  EXPECT_EQ(FilmKinetics(s_r, k_g).steady_state(0.0), 1.0);   // at rest it grows back completely
  EXPECT_EQ(FilmKinetics::advance(0.37, 0.0, 0.0), 0.37);
}

TEST(SurfaceFilm, CoefficientChecks)
{
  EXPECT_EQ(message_of([] { FilmKinetics(-1e-6, 0.0); }),
            "s_r: film removal distance must be >= 0 m (0: no removal), got -1e-06");
  EXPECT_EQ(message_of([] { FilmKinetics(1e-6, -2.0); }), "k_g: film growth rate must be >= 0 1/s (0: no growth), got -2");
  EXPECT_EQ(message_of([] { FilmKinetics(1e-6, HUGE_VAL); }), "k_g: film growth rate must be >= 0 1/s (0: no growth), got inf");
  EXPECT_EQ(message_of([] { FilmKinetics::checked_coverage(1.5); }), "coverage: film coverage must be in [0, 1], got 1.5");
  EXPECT_EQ(message_of([] { FilmKinetics::checked_coverage(-0.1); }),
            "coverage: film coverage must be in [0, 1], got -0.1");
  EXPECT_EQ(FilmKinetics::checked_coverage(1.0), 1.0);
  EXPECT_EQ(FilmKinetics::interpolate(1.0, 0.8, 0.2), 0.2);    // exact at the ends
  EXPECT_EQ(FilmKinetics::interpolate(0.0, 0.8, 0.2), 0.8);
}

// The friction of a plastic junction (30 omega_c) sheared at constant normal load follows the film: at coverage 1
// Tabor's mu of f_film, at 0 of f_clean, in between of the interpolated f; the model's kinetics remove slip / s_r.
TEST(SurfaceFilm, JunctionFrictionFollowsTheCoverage)
{
  const double f_clean = 0.8, f_film = 0.2, alpha = 12.0, s_r = 1e-7, R = 2e-5;
  const auto choice = film_choice();
  const tribo::ContactModel model(choice, tribo::contact_coefficients(choice, steel(f_clean, f_film, s_r)), {});
  ASSERT_NE(model.film_kinetics(), nullptr);
  EXPECT_EQ(model.film_kinetics()->removal_distance(), s_r);
  EXPECT_DOUBLE_EQ(model.film_kinetics()->removal(3e-9), 3e-9 / s_r);
  const double omega_c = tribo::JacksonGreen(1.092e11, R, 350e6, 0.29).critical_interference();
  for (double theta : {1.0, 0.0, 0.25, 0.5}) {
    double history[tribo::CONTACT_HISTORY_SIZE] = {0.0};
    tribo::ContactGeometry g;
    g.effective_radius = R;
    g.effective_mass = 1e-9;
    g.normal[2] = 1.0;
    g.film_coverage = theta;
    for (int k = 1; k <= 100; ++k) {
      g.overlap = 30.0 * omega_c * k / 100.0;
      model.evaluate<kElasticPlastic, kJunctionFilm, 0>(g, history, 1e-9, true);
    }
    g.tangential_velocity[0] = 1e-2;
    tribo::ContactResult r;
    for (int k = 0; k < 3000; ++k) r = model.evaluate<kElasticPlastic, kJunctionFilm, 0>(g, history, 1e-9, true);
    ASSERT_TRUE(r.tangential.slipping) << theta;
    const double f = theta * f_film + (1.0 - theta) * f_clean;
    EXPECT_NEAR(r.tangential.force_magnitude / r.normal_force, tabor(f, alpha), 1e-12) << theta;
    EXPECT_GT(r.tangential.slip_increment, 0.0);
  }
  // without a film model there is no film: no kinetics, no exposure
  tribo::ContactModelChoice plain = choice;
  plain.index[static_cast<int>(SubModelKind::friction)] = tribo::find_sub_model(SubModelKind::friction, "junction");
  tribo::ContactParameters p = steel(0.5, 0.2);
  p.film_interface_coefficient = std::nan("");
  p.film_removal_distance = p.film_growth_rate = std::nan("");
  EXPECT_EQ(tribo::ContactModel(plain, tribo::contact_coefficients(plain, p), {}).film_kinetics(), nullptr);
}

// The explicit parameters: f_film needed; s_r and k_g off unless given; a film's values on a model without a film
// are refused, naming the value; f_clean and f_film named in the junction's checks; the normal model checked.
TEST(SurfaceFilm, ParametersAndChecks)
{
  const auto choice = film_choice();
  const auto built = [&](const tribo::ContactParameters &p) {
    return [p, choice] { tribo::ContactModel(choice, tribo::contact_coefficients(choice, p), {}); };
  };
  tribo::ContactParameters p = steel(0.8, 0.2);
  p.film_removal_distance = p.film_growth_rate = std::nan("");
  EXPECT_EQ(tribo::contact_coefficients(choice, p).of(SubModelKind::friction),
            (tribo::Coefficients{0.8, 0.2, 12.0, 0.0, 0.0}));
  p.film_interface_coefficient = std::nan("");
  EXPECT_EQ(message_of(built(p)).rfind("f_film: friction model 'junction/film' needs the film's interface coefficient", 0), 0u);
  EXPECT_EQ(message_of(built(steel(1.0, 0.2))).rfind("f_clean: interface coefficient must be in [0, 1)", 0), 0u);
  EXPECT_EQ(message_of(built(steel(0.8, 1.0))).rfind("f_film: interface coefficient must be in [0, 1)", 0), 0u);
  EXPECT_EQ(message_of(built(steel(0.8, 0.2, -1e-6))), "s_r: film removal distance must be >= 0 m (0: no removal), got -1e-06");
  EXPECT_EQ(message_of(built(steel(0.8, 0.2, 1e-6, -1.0))), "k_g: film growth rate must be >= 0 1/s (0: no growth), got -1");
  tribo::ContactModelChoice strength;
  strength.index[static_cast<int>(SubModelKind::friction)] = tribo::find_sub_model(SubModelKind::friction, "strength");
  tribo::ContactParameters q = steel(0.8, std::nan(""), 1e-6);
  q.film_growth_rate = std::nan("");
  EXPECT_EQ(message_of([&] { tribo::contact_coefficients(strength, q); }),
            "s_r: friction model 'strength' has no surface film (film keywords need friction junction/film)");
  tribo::ContactModelChoice hertz = choice;
  hertz.index[static_cast<int>(SubModelKind::normal)] = 0;
  EXPECT_EQ(message_of([&] { tribo::ContactModel(hertz, tribo::contact_coefficients(hertz, steel(0.8, 0.2)), {}); }),
            "friction model 'junction/film' needs the normal model 'elastic/plastic'");
}

TEST(SurfaceFilm, MixingAndRestartRecord)
{
  const auto choice = film_choice();
  const auto ii = tribo::contact_coefficients(choice, steel(0.8, 0.2, 1e-6, 1e3));
  const auto jj = tribo::contact_coefficients(choice, steel(0.5, 0.2, 4e-6, 4e3));
  const auto mixed = tribo::mix_coefficients(choice, ii, jj);
  const tribo::Coefficients &f = mixed.of(SubModelKind::friction);
  EXPECT_NEAR(f[0], std::sqrt(0.4), 1e-15);
  EXPECT_NEAR(f[3], 2e-6, 1e-21);
  EXPECT_NEAR(f[4], 2e3, 1e-12);
  const auto record = tribo::serialize(choice, ii);
  const auto back = tribo::deserialize(record.data(), static_cast<int>(record.size()));
  EXPECT_TRUE(back.first == choice);
  EXPECT_EQ(back.second.of(SubModelKind::friction), ii.of(SubModelKind::friction));
}
