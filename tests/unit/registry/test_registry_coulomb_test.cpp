// A friction law added as one class and one registry row (coulomb_test_friction.h, test build only): the registry,
// the coefficient grammar's three forms, mixing, restart records, the generated messages and the compile-time
// dispatch of the kernel all know it without a line elsewhere.
#include "../coefficient_test_host.h"
#include "tribo/contact_model.h"

#include <gtest/gtest.h>

#include <string>

namespace {

namespace tribo = runin::tribo;
using runin_test::choice_of;
using runin_test::Failed;
using tribo::SubModelKind;

tribo::ContactCoefficients pair_coeff(const std::string &line, tribo::ContactModelChoice choice)
{
  runin_test::CoefficientTestHost t(true);
  runin_test::Words w(line);
  return runin_coeff::pair_coeff(t.host, w.narg(), w.arg.data(), choice, tribo::ContactSettings());
}

std::string error_of(const std::string &line, tribo::ContactModelChoice choice)
{
  try {
    pair_coeff(line, choice);
  } catch (const Failed &e) {
    return e.what();
  }
  return "accepted";
}

const char *const kBlock = "1 1 normal hertz 4.8e10 damping restitution 0.5 tangential mindlin 1.9e10 "
                           "friction coulomb_test 0.4 wear archard 1e-3 1e9 1e-3 1e9";
const char *const kExplicit = "1 1 4.8e10 1.9e10 0.5 0.6 0.4 0.0 1e-3 1e9";

}    // namespace

TEST(RegistryTestModel, IsRegisteredWithItsCoefficientsAndNoCapabilities)
{
  const auto &friction = tribo::registered_sub_models(SubModelKind::friction);
  ASSERT_EQ(std::string(friction.back().name), "coulomb_test");
  ASSERT_EQ(friction.back().coefficient_count(), 1);
  EXPECT_EQ(std::string(friction.back().coefficient_names[0]), "mu");
  EXPECT_FALSE(friction.back().has_film);
  EXPECT_EQ(friction.back().interface_use, tribo::InterfaceUse::none);
  try {
    tribo::find_sub_model(SubModelKind::friction, "amontons");
    FAIL() << "an unknown friction model was accepted";
  } catch (const tribo::InvalidCoefficient &e) {
    // the shipped names (from the registry), then the test row
    const std::string known = tribo::registered_names(SubModelKind::friction);
    EXPECT_EQ(known.substr(known.size() - std::string(", coulomb_test").size()), ", coulomb_test");
    EXPECT_EQ(std::string(e.what()), "unknown friction model 'amontons' (known: " + known + ")");
  }
}

// The keyword block reads its one coefficient; the explicit form fills it from mu_k (its from_parameters).
TEST(RegistryTestModel, KeywordBlockAndExplicitFormGiveTheSameCoefficients)
{
  const auto choice = choice_of("hertz", "coulomb_test");
  const auto block = pair_coeff(kBlock, choice);
  const auto explicit_form = pair_coeff(kExplicit, choice);
  EXPECT_EQ(block.of(SubModelKind::friction), tribo::Coefficients{0.4});
  for (int k = 0; k < tribo::kSubModelKinds; ++k) EXPECT_EQ(block.values[k], explicit_form.values[k]) << "kind " << k;
  EXPECT_EQ(error_of("1 1 normal hertz 4.8e10 damping restitution 0.5 tangential mindlin 1.9e10 friction "
                     "coulomb_test 0.4 0.3 wear archard 1e-3 1e9 1e-3 1e9", choice),
            "pair_coeff runin/asperity: friction model 'coulomb_test' takes 1 coefficient(s) (mu), got 2");
  EXPECT_EQ(error_of("1 1 normal hertz 4.8e10 damping restitution 0.5 tangential mindlin 1.9e10 friction "
                     "coulomb_test -0.4 wear archard 1e-3 1e9 1e-3 1e9", choice),
            "pair_coeff runin/asperity (keywords): mu: friction coefficient must be >= 0");
}

// The messages that list laws by capability are generated from the registry.
TEST(RegistryTestModel, CapabilityMessagesNameItFromTheRegistry)
{
  const auto choice = choice_of("hertz", "coulomb_test");
  EXPECT_EQ(error_of(std::string(kExplicit) + " f_film 0.2", choice),
            "pair_coeff runin/asperity (explicit): f_film: friction model 'coulomb_test' has no surface film (film "
            "keywords need friction junction/film)");
  tribo::ContactParameters p;
  p.interface_state = 1;
  p.interface_factors[1] = 0.5;
  try {
    tribo::contact_coefficients(choice, p);
    FAIL() << "an interface state was accepted by a law without an interface strength";
  } catch (const tribo::InvalidCoefficient &e) {
    EXPECT_EQ(std::string(e.what()), "interface: friction model 'coulomb_test' has no interface strength (interface "
                                     "oxidised sets tau_s of 'strength' and 'brizmer' or f of 'junction')");
  }
}

TEST(RegistryTestModel, MixesAndRoundTripsThroughRestartRecords)
{
  const auto choice = choice_of("elastic/plastic", "coulomb_test");
  tribo::ContactCoefficients ii = pair_coeff("1 1 normal elastic/plastic 1.092e11 3.5e8 0.29 damping restitution 0.5 "
                                             "tangential mindlin 4.3e10 friction coulomb_test 0.16 wear archard 0 1e9 "
                                             "0 1e9", choice);
  tribo::ContactCoefficients jj = ii;
  jj.of(SubModelKind::friction) = {0.64};
  EXPECT_EQ(tribo::mix_coefficients(choice, ii, jj).of(SubModelKind::friction), tribo::Coefficients{0.32});
  const auto record = tribo::serialize(choice, ii);
  const auto back = tribo::deserialize(record.data(), static_cast<int>(record.size()));
  EXPECT_TRUE(back.first == choice);
  EXPECT_EQ(back.second.of(SubModelKind::friction), ii.of(SubModelKind::friction));
  EXPECT_EQ(tribo::describe(choice),
            "normal elastic/plastic damping restitution tangential mindlin friction coulomb_test wear archard");
}

// Through the compile-time dispatch (with_sub_models, as the hosts' eval tables), a sliding contact's tangential
// force is mu F_n: the same digits as coulomb with mu_s = mu_k = mu.
TEST(RegistryTestModel, KernelDispatchGivesCoulombsForce)
{
  const auto test_choice = choice_of("hertz", "coulomb_test");
  const auto coulomb_choice = choice_of("hertz", "coulomb");
  const tribo::ContactModel test_model(test_choice, pair_coeff(kBlock, test_choice), tribo::ContactSettings());
  const tribo::ContactModel coulomb(coulomb_choice,
                                    pair_coeff("1 1 normal hertz 4.8e10 damping restitution 0.5 tangential mindlin "
                                               "1.9e10 friction coulomb 0.4 0.4 0.0 wear archard 1e-3 1e9 1e-3 1e9",
                                               coulomb_choice),
                                    tribo::ContactSettings());
  const double del[3] = {0.0, 0.0, 2.0e-6 - 1.0e-9}, vi[3] = {0.3, 0.0, 0.0}, vj[3] = {0.0, 0.0, 0.0},
               w[3] = {0.0, 0.0, 0.0};
  const tribo::ContactGeometry g =
      tribo::sphere_sphere_geometry(1.0e-9, 1.0 / del[2], del, 0.0, 1.0e-6, 1.0e-6, 1e-14, 1e-14, vi, vj, w, w);
  double h_test[tribo::CONTACT_HISTORY_SIZE] = {0.0}, h_coulomb[tribo::CONTACT_HISTORY_SIZE] = {0.0};
  tribo::ContactResult r_test, r_coulomb;
  for (int step = 0; step < 50; ++step) {
    tribo::with_sub_models(test_choice, [&](auto normal, auto friction) {
      r_test = test_model.evaluate<decltype(normal)::value, decltype(friction)::value, 1>(g, h_test, 1e-9, true);
    });
    tribo::with_sub_models(coulomb_choice, [&](auto normal, auto friction) {
      r_coulomb = coulomb.evaluate<decltype(normal)::value, decltype(friction)::value, 1>(g, h_coulomb, 1e-9, true);
    });
  }
  ASSERT_TRUE(r_test.tangential.slipping);
  EXPECT_DOUBLE_EQ(r_test.tangential.force_magnitude, 0.4 * r_test.normal_force);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(r_test.tangential.force[k], r_coulomb.tangential.force[k]);
  EXPECT_EQ(r_test.worn_volume, r_coulomb.worn_volume);
}
