// The one contact model (src/tribo/contact_model.h): registry, coefficient checks, mixing, restart records,
// and the elastic-plastic sub-model's cached unloading path against the kernel of elastic_plastic.h.
#include "tribo/contact_model.h"

#include <gtest/gtest.h>

#include <cfenv>
#include <fstream>
#include <sstream>
#include <cmath>
#include <string>

namespace tribo = runin::tribo;
using tribo::SubModelKind;

namespace {

tribo::ContactModelChoice choice_of(const char *normal, const char *friction)
{
  tribo::ContactModelChoice c;
  c.index[static_cast<int>(SubModelKind::normal)] = tribo::find_sub_model(SubModelKind::normal, normal);
  c.index[static_cast<int>(SubModelKind::friction)] = tribo::find_sub_model(SubModelKind::friction, friction);
  return c;
}

tribo::ContactParameters steel()
{
  tribo::ContactParameters p;
  p.effective_modulus = 1.092e11;
  p.effective_shear_modulus = 4.3e10;
  p.restitution = 1.0;
  p.mu_static = 0.5;
  p.mu_kinetic = 0.4;
  p.slip_weakening_distance = 2e-8;
  p.wear_coefficient = 1e-3;
  p.hardness_i = 1.19e9;
  p.hardness_j = 6.0e9;
  p.shear_strength = 2e7;
  p.yield_strength = 350e6;
  p.poisson_ratio = 0.29;
  return p;
}

}    // namespace

TEST(ContactModelRegistry, NamesAndUnknownModelsListTheKnownOnes)
{
  EXPECT_EQ(tribo::find_sub_model(SubModelKind::normal, "hertz"), 0);
  EXPECT_EQ(tribo::find_sub_model(SubModelKind::normal, "elastic/plastic"), 1);
  try {
    tribo::find_sub_model(SubModelKind::friction, "amontons");
    FAIL() << "an unknown friction model was accepted";
  } catch (const tribo::InvalidCoefficient &e) {
    // the registry's names in its order (a new row needs no edit here)
    const auto &friction = tribo::registered_sub_models(SubModelKind::friction);
    std::string known;
    for (const auto &info : friction) known += (known.empty() ? "" : ", ") + std::string(info.name);
    EXPECT_EQ(tribo::registered_names(SubModelKind::friction), known);
    EXPECT_EQ(std::string(e.what()), "unknown friction model 'amontons' (known: " + known + ")");
  }
}

// runin homogenise offers a cell the laws an interface state sets (its f or tau_s from the material file's line), by
// their capability; its default is the first that takes the state as tau_s, which must be the cell deck's own default
// (inputs/in.rve_rough, `variable friction index ...`): the CLI passes no friction to the deck for it.
TEST(ContactModelRegistry, InterfaceFrictionModelsFollowTheirCapability)
{
  std::vector<std::string> expected;
  for (const auto &info : tribo::registered_sub_models(SubModelKind::friction))
    if (info.interface_use != tribo::InterfaceUse::none) expected.push_back(info.name);
  EXPECT_EQ(tribo::interface_friction_models(), expected);
  ASSERT_GE(expected.size(), 2u);
  const std::string fallback = tribo::default_interface_friction_model();
  EXPECT_EQ(tribo::registered_sub_models(SubModelKind::friction)[tribo::find_sub_model(SubModelKind::friction, fallback)]
                .interface_use,
            tribo::InterfaceUse::shear_strength);
  std::ifstream deck(std::string(RUNIN_SOURCE_DIR) + "/inputs/in.rve_rough");
  std::string line, deck_default;
  while (std::getline(deck, line)) {
    std::istringstream words(line);
    std::string command, name, style;
    if (words >> command >> name >> style >> deck_default && command == "variable" && name == "friction") break;
    deck_default.clear();
  }
  EXPECT_EQ(fallback, deck_default) << "the cell deck's default friction differs from the registry's default";
}

// The history layout is placed from the slots the models declare (the tangential model's, then the normal model's),
// and the slots the registry says flip with the body order are what the hosts negate when they see a contact from
// the other body (the pair's transfer_history, LIGGGHTS's contact history flags): the same contact from j, with its
// history so transformed, gives the opposite tangential force and the same slip, every digit.
TEST(ContactModelRegistry, HistoryLayoutFollowsTheDeclaredSlotsAndFlipsWithTheBodies)
{
  EXPECT_EQ(tribo::kNormalHistoryOffset, tribo::kTangentialHistoryOffset + tribo::TangentialHistory::history_slots);
  constexpr int hertz_size = tribo::contact_history_size<0>;
  using Hertz = std::tuple_element_t<0, tribo::NormalModels>;
  EXPECT_EQ(hertz_size, tribo::kNormalHistoryOffset + Hertz::history_slots);
  EXPECT_EQ(tribo::contact_history_size_of(1), tribo::contact_history_size<1>);
  int flipping = 0;
  for (int k = 0; k < tribo::CONTACT_HISTORY_SIZE; ++k) flipping += tribo::history_flips_with_bodies(k);
  EXPECT_EQ(flipping, 3);    // one vector in the tangent plane
  EXPECT_FALSE(tribo::history_flips_with_bodies(tribo::kSlipHistorySlot));

  const auto choice = choice_of("elastic/plastic", "coulomb");
  const tribo::ContactModel model(choice, tribo::contact_coefficients(choice, steel()), {});
  auto geometry = [](double sign) {
    tribo::ContactGeometry g;
    g.overlap = 2e-8;
    g.effective_radius = 2e-5;
    g.effective_mass = 1e-9;
    g.normal[2] = sign;
    g.tangential_velocity[0] = sign * 0.3;
    g.tangential_velocity[1] = sign * 0.1;
    return g;
  };
  double hi[tribo::CONTACT_HISTORY_SIZE] = {0.0}, hj[tribo::CONTACT_HISTORY_SIZE] = {0.0};
  for (int step = 0; step < 40; ++step) model.evaluate<1, 0, 0>(geometry(1.0), hi, 1e-9, true);
  ASSERT_GT(hi[tribo::kSlipHistorySlot], 0.0) << "the contact never slipped";
  for (int k = 0; k < tribo::CONTACT_HISTORY_SIZE; ++k) hj[k] = tribo::history_flips_with_bodies(k) ? -hi[k] : hi[k];
  const auto from_i = model.evaluate<1, 0, 0>(geometry(1.0), hi, 1e-9, true);
  const auto from_j = model.evaluate<1, 0, 0>(geometry(-1.0), hj, 1e-9, true);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(from_j.tangential.force[k], -from_i.tangential.force[k]) << k;
  EXPECT_GT(from_i.tangential.force_magnitude, 0.0);
  EXPECT_EQ(hj[tribo::kSlipHistorySlot], hi[tribo::kSlipHistorySlot]);
}

TEST(ContactModelRegistry, WrongCoefficientCountNamesTheExpectedOnes)
{
  const auto choice = choice_of("elastic/plastic", "coulomb");
  tribo::ContactCoefficients c = tribo::contact_coefficients(choice, steel());
  c.of(SubModelKind::normal).pop_back();
  try {
    tribo::check_coefficient_counts(choice, c);
    FAIL() << "a short coefficient list was accepted";
  } catch (const tribo::InvalidCoefficient &e) {
    EXPECT_EQ(std::string(e.what()), "normal model 'elastic/plastic' takes 3 coefficient(s) (E* S_y nu), got 2");
  }
}

TEST(ContactModelRegistry, ImpossibleCoefficientsNameTheCoefficient)
{
  const auto choice = choice_of("elastic/plastic", "brizmer");
  tribo::ContactParameters p = steel();
  p.yield_strength = -1.0;
  EXPECT_THROW(tribo::ContactModel(choice, tribo::contact_coefficients(choice, p), {}), tribo::InvalidCoefficient);
  p = steel();
  p.poisson_ratio = 0.1;    // outside the Brizmer fit
  try {
    tribo::ContactModel(choice, tribo::contact_coefficients(choice, p), {});
    FAIL() << "nu = 0.1 was accepted by the brizmer friction model";
  } catch (const tribo::InvalidCoefficient &e) {
    EXPECT_EQ(std::string(e.what()).rfind("nu: friction model 'brizmer'", 0), 0u) << e.what();
  }
  EXPECT_THROW(tribo::ContactModel(choice_of("hertz", "brizmer"),
                                   tribo::contact_coefficients(choice_of("hertz", "brizmer"), steel()), {}),
               tribo::InvalidCoefficient);
}

// 1/E*_ij = (1 - nu_i^2)/E_i + (1 - nu_j^2)/E_j: mixing the like pairs gives it exactly.
TEST(ContactModelMixing, EffectiveModuliOfUnlikeMaterialsAreExact)
{
  const tribo::Material al{69e9, 0.33, 0.245e9, 34e6}, cu{110e9, 0.37, 0.87e9, 250e6};
  const auto choice = choice_of("elastic/plastic", "coulomb");
  const auto ii = tribo::contact_coefficients(choice, tribo::contact_parameters(al, al, 0.5, 0.6, 0.4, 0.0, 1e-3));
  const auto jj = tribo::contact_coefficients(choice, tribo::contact_parameters(cu, cu, 0.5, 0.6, 0.4, 0.0, 1e-3));
  const auto ij = tribo::mix_coefficients(choice, ii, jj);
  EXPECT_NEAR(ij.of(SubModelKind::normal)[0], tribo::effective_modulus(al, cu), 1e-15 * 5e10);
  EXPECT_NEAR(ij.of(SubModelKind::tangential)[0], tribo::effective_shear_modulus(al, cu), 1e-15 * 2e10);
  EXPECT_EQ(ij.of(SubModelKind::normal)[1], 34e6);    // the softer body yields
  // each body keeps its own wear coefficient and hardness
  EXPECT_EQ(ij.of(SubModelKind::wear)[1], al.hardness);
  EXPECT_EQ(ij.of(SubModelKind::wear)[3], cu.hardness);
}

TEST(ContactModelRestart, RecordRoundTripsAndNamesADifferentChoice)
{
  const auto choice = choice_of("elastic/plastic", "strength");
  const auto c = tribo::contact_coefficients(choice, steel());
  const std::vector<double> record = tribo::serialize(choice, c);
  const auto back = tribo::deserialize(record.data(), static_cast<int>(record.size()));
  EXPECT_TRUE(back.first == choice);
  for (int k = 0; k < tribo::kSubModelKinds; ++k) EXPECT_EQ(back.second.values[k], c.values[k]);
  EXPECT_EQ(tribo::describe_difference(back.first, choice_of("hertz", "strength")),
            "normal model: restart 'elastic/plastic', input 'hertz'");
  EXPECT_THROW(tribo::deserialize(record.data(), static_cast<int>(record.size()) - 3), tribo::InvalidCoefficient);
}

// The elastic-plastic sub-model caches each contact's unloading curve in the history; along a load-unload-
// reload path it must give the kernel's elastic_plastic_contact() (the published equations) to round-off.
TEST(ContactModelElasticPlastic, CachedHistoryPathEqualsTheKernel)
{
  const auto choice = choice_of("elastic/plastic", "coulomb");
  const tribo::ContactParameters p = steel();
  const tribo::ContactModel model(choice, tribo::contact_coefficients(choice, p), {});
  const double R = 2e-5;
  const tribo::JacksonGreen curve(p.effective_modulus, R, p.yield_strength, p.poisson_ratio);
  const double omega_c = curve.critical_interference();
  double history[tribo::CONTACT_HISTORY_SIZE] = {0.0};
  double omega_max = 0.0;
  int checked = 0;
  // 0 -> 30 omega_c -> 5 omega_c -> 60 omega_c
  for (double target : {30.0, 5.0, 60.0}) {
    const double start = checked == 0 ? 0.0 : (target == 5.0 ? 30.0 : 5.0);
    for (int k = 1; k <= 200; ++k) {
      const double omega = (start + (target - start) * k / 200.0) * omega_c;
      tribo::ContactGeometry g;
      g.overlap = omega;
      g.effective_radius = R;
      g.effective_mass = 1.0;
      g.normal[2] = 1.0;
      const tribo::ContactResult got = model.evaluate<1, 0, 0>(g, history, 1e-9, true);
      const tribo::ElasticPlasticContact want = tribo::elastic_plastic_contact(curve, omega, omega_max);
      omega_max = want.omega_max;
      EXPECT_NEAR(got.normal.force, want.force, 1e-12 * curve.force(60.0 * omega_c)) << omega / omega_c;
      EXPECT_NEAR(got.normal.contact_radius, want.contact_radius, 1e-12 * R) << omega / omega_c;
      EXPECT_NEAR(history[tribo::kNormalHistoryOffset + tribo::ElasticPlasticNormalModel::MAX_OVERLAP], omega_max, 1e-15 * omega_max);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 600);
}

// Reloading a summit that plastic flattening lowered is one physics for every host: fix runin/wall keeps the
// plastic history of its asperity (omega_max and the EKK curve), pair runin/asperity starts a new contact of the
// same summits without it and passes the flattened drop. Loaded to omega* = 95, unloaded until it opens (the
// summits sink to the EKK residual interference), then reloaded to 120 omega_c: both give the same force and
// contact radius to 1e-9, on the EKK unloading curve below omega_max and the JG curve beyond. The seeded
// omega_max is the one that made the flat (EKK residual inverted, 1e-12). A worn flat (no flattened drop) still
// reloads by Sneddon's flat punch + Hertz.
TEST(ContactModelElasticPlastic, ReloadOfAFlattenedSummitIsTheSameWithOrWithoutKeptHistory)
{
  const auto choice = choice_of("elastic/plastic", "coulomb");
  const tribo::ContactParameters p = steel();
  const tribo::ContactModel model(choice, tribo::contact_coefficients(choice, p), {});
  const double R = 2e-5;
  const tribo::JacksonGreen curve(p.effective_modulus, R, p.yield_strength, p.poisson_ratio);
  const double omega_c = curve.critical_interference();
  double kept[tribo::CONTACT_HISTORY_SIZE] = {0.0};
  double drop = 0.0, omega_max = 0.0;
  auto geometry = [&](double omega) {
    tribo::ContactGeometry g;
    g.overlap = omega - drop;
    g.summit_drop = drop;
    g.flat_radius = drop > 0.0 ? std::sqrt(2.0 * R * drop - drop * drop) : 0.0;
    g.effective_radius = R;
    g.effective_mass = 1.0;
    g.normal[2] = 1.0;
    return g;
  };
  // load to 95 omega_c and unload to the residual: the summit sinks by the residual increments
  for (int k = 1; k <= 400; ++k) {
    const double omega = (k <= 200 ? 95.0 * k / 200.0 : 95.0 * (400 - k) / 200.0) * omega_c;
    if (omega <= drop) break;
    const tribo::ContactResult r = model.evaluate<1, 0, 0>(geometry(omega), kept, 1e-9, true);
    drop += r.normal.residual_increment;
    omega_max = std::max(omega_max, omega);
  }
  const double residual = tribo::ElasticPlasticUnloading::residual_ratio(95.0) * 95.0 * omega_c;
  ASSERT_NEAR(drop, residual, 1e-12 * residual);
  ASSERT_NEAR(kept[tribo::kNormalHistoryOffset + tribo::ElasticPlasticNormalModel::MAX_OVERLAP], 95.0 * omega_c, 1e-12 * omega_c);
  double fresh[tribo::CONTACT_HISTORY_SIZE] = {0.0};    // the pair: the summits separated, the history is gone
  const double scale = curve.force(95.0 * omega_c);
  int ekk = 0, plastic = 0;
  for (int k = 1; k <= 300; ++k) {
    const double omega = drop + (120.0 * omega_c - drop) * k / 300.0;
    tribo::ContactGeometry wall = geometry(omega), pair = geometry(omega);
    wall.flattened_drop = 0.0;    // the wall's history explains the drop (a host sets it only without history)
    if (!(fresh[tribo::kNormalHistoryOffset + tribo::ElasticPlasticNormalModel::MAX_OVERLAP] > 0.0)) pair.flattened_drop = drop;
    const tribo::ContactResult a = model.evaluate<1, 0, 0>(wall, kept, 1e-9, true);
    const tribo::ContactResult b = model.evaluate<1, 0, 0>(pair, fresh, 1e-9, true);
    if (k == 1) EXPECT_NEAR(fresh[tribo::kNormalHistoryOffset + tribo::ElasticPlasticNormalModel::MAX_OVERLAP], 95.0 * omega_c, 1e-12 * 95.0 * omega_c);
    EXPECT_NEAR(b.normal.force, a.normal.force, 1e-9 * std::max(a.normal.force, 1e-3 * scale)) << omega / omega_c;
    EXPECT_NEAR(b.normal.contact_radius, a.normal.contact_radius, 1e-9 * std::max(a.normal.contact_radius, 1e-3 * R))
        << omega / omega_c;
    EXPECT_NEAR(b.normal.residual_increment, a.normal.residual_increment, 1e-9 * residual) << omega / omega_c;
    drop += a.normal.residual_increment;
    (omega <= omega_max ? ekk : plastic) += 1;
    if (omega <= omega_max) {
      const double want = tribo::ElasticPlasticUnloading(curve, omega_max).force(omega);
      EXPECT_NEAR(b.normal.force, want, 1e-9 * scale) << omega / omega_c;
    }
  }
  EXPECT_GT(ekk, 100);
  EXPECT_GT(plastic, 50);
  // the inverse of the residual ratio, over the range of the fits and beyond
  for (double x : {1.001, 1.5, 1.9, 10.0, 95.0, 110.0, 1000.0, 1e5}) {
    const double d = tribo::ElasticPlasticUnloading::residual_ratio(x) * x;
    EXPECT_NEAR(tribo::ElasticPlasticUnloading::max_interference_of_residual(d), x, 1e-12 * x) << x;
  }
}

// A worn flat reloaded elastically (Sneddon) touches the counterface over pi a^2 at any load; its adhesion area
// is that of its plastic micro-contacts, F / (2.84 S_y), up to pi a^2. An intact sphere keeps pi a^2 (JG).
TEST(ContactModelElasticPlastic, WornFlatCarriesItsLoadOnPlasticMicroContacts)
{
  const auto choice = choice_of("elastic/plastic", "strength");
  const tribo::ContactParameters p = steel();
  const tribo::ContactModel model(choice, tribo::contact_coefficients(choice, p), {});
  const double R = 2e-5, drop = 5e-8, pi = 3.14159265358979323846;
  const double flat = std::sqrt(2.0 * R * drop - drop * drop);
  const double flow_pressure = 2.84 * p.yield_strength;
  for (double overlap : {1e-11, 1e-10, 1e-9}) {
    double history[tribo::CONTACT_HISTORY_SIZE] = {0.0};
    tribo::ContactGeometry g;
    g.overlap = overlap;
    g.effective_radius = R;
    g.effective_mass = 1.0;
    g.flat_radius = flat;
    g.summit_drop = drop;
    g.normal[2] = 1.0;
    const tribo::ContactResult got = model.evaluate<1, 1, 0>(g, history, 1e-9, true);
    const tribo::FlatHertzContact sneddon = tribo::flat_hertz_contact(p.effective_modulus, R, flat, overlap);
    ASSERT_NEAR(got.normal.force, sneddon.force, 1e-12 * sneddon.force) << overlap;
    const double conforming = pi * sneddon.contact_radius * sneddon.contact_radius;
    const double micro = sneddon.force / flow_pressure;
    ASSERT_LT(micro, conforming) << overlap;    // the flat's mean pressure is below the flow pressure
    EXPECT_NEAR(got.normal.real_area, micro, 1e-12 * micro) << overlap;
    EXPECT_NEAR(got.strength.adhesion, p.shear_strength * micro, 1e-12 * p.shear_strength * micro) << overlap;
    EXPECT_EQ(got.strength.ploughing, 0.0);
  }
  // where the flat's mean pressure reaches the flow pressure the area is the whole flat
  const tribo::ElasticPlasticNormalModel normal(
      tribo::contact_coefficients(choice, p).of(SubModelKind::normal).data());
  EXPECT_DOUBLE_EQ(normal.worn_flat_real_area(2.0 * flow_pressure * pi * flat * flat, flat), pi * flat * flat);
  EXPECT_DOUBLE_EQ(normal.micro_contact_flow_pressure(), flow_pressure);
  // an intact sphere: the Jackson-Green area
  const tribo::JacksonGreen curve(p.effective_modulus, R, p.yield_strength, p.poisson_ratio);
  double history[tribo::CONTACT_HISTORY_SIZE] = {0.0};
  tribo::ContactGeometry g;
  g.overlap = 5.0 * curve.critical_interference();
  g.effective_radius = R;
  g.effective_mass = 1.0;
  g.normal[2] = 1.0;
  const tribo::ContactResult sphere = model.evaluate<1, 1, 0>(g, history, 1e-9, true);
  EXPECT_NEAR(sphere.normal.real_area, curve.contact_area(g.overlap), 1e-12 * curve.contact_area(g.overlap));
}

// Subnormal numbers cost the force loops up to a hundred cycles per operation (the Mindlin drop test once
// formed 1e-300 |xi|^2 of a micrometre spring and halved the pair's speed). A sliding contact of
// the micro decks' scale (R* = 0.5 um, nm overlaps, m/s, dt = 0.1 ns), loaded, unloaded and reloaded with
// the normal turning every step, must not raise the underflow flag with any normal and friction model.
namespace {
template <int NORMAL, int FRICTION> bool contact_sequence_underflows(const tribo::ContactParameters &p)
{
  tribo::ContactModelChoice choice;
  choice.index[static_cast<int>(SubModelKind::normal)] = NORMAL;
  choice.index[static_cast<int>(SubModelKind::friction)] = FRICTION;
  tribo::ContactSettings settings;
  settings.transfer_fraction = 0.3;
  settings.restick_speed = 0.01;
  const tribo::ContactModel model(choice, tribo::contact_coefficients(choice, p), settings);
  double history[tribo::CONTACT_HISTORY_SIZE] = {0.0};
  std::feclearexcept(FE_ALL_EXCEPT);
  volatile double sink = 0.0;
  for (int step = 0; step < 3000; ++step) {
    const double phase = 2.0 * 3.14159265358979323846 * step / 1000.0;    // three load cycles
    const double tilt = 1e-3 * std::sin(0.37 * step);                        // the normal turns
    tribo::ContactGeometry g;
    g.overlap = 2e-9 * (1.2 - std::cos(phase));
    g.effective_radius = 5e-7;
    g.effective_mass = 5e-15;
    g.normal[0] = std::sin(tilt);
    g.normal[2] = std::cos(tilt);
    g.normal_velocity = -2e-9 * std::sin(phase) * 2.0 * 3.14159265358979323846 / 1000.0 / 1e-10;
    g.tangential_velocity[0] = 2.0 * std::cos(tilt);
    g.tangential_velocity[1] = 0.5 * std::sin(0.01 * step);
    g.tangential_velocity[2] = -2.0 * std::sin(tilt);
    const tribo::ContactResult r = model.evaluate<NORMAL, FRICTION, 1>(g, history, 1e-10, true);
    sink = sink + r.normal_force + r.tangential.force[0] + r.worn_volume + r.normal.real_area;
  }
  const bool underflow = std::fetestexcept(FE_UNDERFLOW) != 0;
  EXPECT_TRUE(std::isfinite(sink));
  return underflow;
}
}    // namespace

TEST(ContactModelArithmetic, MicroScaleContactsStayOutOfSubnormals)
{
  tribo::ContactParameters p = steel();
  p.restitution = 0.5;
  EXPECT_FALSE((contact_sequence_underflows<0, 0>(p))) << "hertz + coulomb";
  EXPECT_FALSE((contact_sequence_underflows<0, 1>(p))) << "hertz + strength";
  EXPECT_FALSE((contact_sequence_underflows<1, 0>(p))) << "elastic/plastic + coulomb";
  EXPECT_FALSE((contact_sequence_underflows<1, 1>(p))) << "elastic/plastic + strength";
  EXPECT_FALSE((contact_sequence_underflows<1, 2>(p))) << "elastic/plastic + brizmer";
}
