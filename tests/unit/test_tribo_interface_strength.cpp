// Interfacial shear strength from the interface state (src/tribo/friction_strength.h, doc/interface_strength.md):
// tau_s = m S_y / sqrt(3) against the closed form, the coefficient files' 'interface A B STATE m' lines, how
// contact_coefficients applies a state to the friction sub-models, and the bad-input checks (m outside [0, 1],
// an unknown state, an interface stronger than the softer body).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "tribo/contact_model.h"
#include "tribo/material_file.h"

namespace tribo = runin::tribo;
using tribo::SubModelKind;

namespace {

constexpr double kInvSqrt3 = 0.57735026918962576451;    // 1 / sqrt(3), von Mises

std::string error_of(void (*body)())
{
  try {
    body();
  } catch (const std::exception &e) {
    return e.what();
  }
  return "";
}

template <class Body> std::string message_of(Body &&body)
{
  try {
    body();
  } catch (const std::exception &e) {
    return e.what();
  }
  return "";
}

tribo::MaterialFile parse(const std::string &text)
{
  std::istringstream in(text);
  return tribo::parse_material_file(in, "x.runin");
}

const std::string kGood =
    "material Cu  110.0e9  0.37  8960.0  0.87e9   250.0e6\n"
    "material Al   69.0e9  0.33  2700.0  0.245e9   34.0e6\n"
    "pair Al Cu  0.5  0.95  0.55  2.0e-8  1.0e-3\n";

tribo::ContactModelChoice choice(const char *normal, const char *friction)
{
  tribo::ContactModelChoice c;
  c.index[static_cast<int>(SubModelKind::normal)] = tribo::find_sub_model(SubModelKind::normal, normal);
  c.index[static_cast<int>(SubModelKind::friction)] = tribo::find_sub_model(SubModelKind::friction, friction);
  return c;
}

// AISI 1020 on itself as the file form gives it (S_y from the material line)
tribo::ContactParameters steel()
{
  tribo::Material m;
  m.youngs_modulus = 200e9;
  m.poisson_ratio = 0.29;
  m.hardness = 1.19e9;
  m.yield_strength = 350e6;
  tribo::ContactParameters p = tribo::contact_parameters(m, m, 0.5, 0.74, 0.57, 2e-8, 7e-3);
  p.interface_factors = {1.0, 0.8921, 0.1};
  return p;
}

double tau_s_of(const tribo::ContactCoefficients &c, const char *friction)
{
  return c.of(SubModelKind::friction)[std::string(friction) == "strength" ? 3 : 1];
}

}    // namespace

TEST(InterfaceStrength, ShearStrengthIsMTimesTheVonMisesShearYield)
{
  for (double yield : {34e6, 250e6, 350e6})
    for (double m : {0.0, 0.05, 0.1, 0.5, 0.8921, 1.0}) {
      const double want = m * yield * kInvSqrt3;
      EXPECT_NEAR(tribo::interface_shear_strength(m, yield), want, 1e-15 * yield) << m << " " << yield;
    }
  EXPECT_NEAR(tribo::shear_yield_strength(350e6), 202072594.21636903, 1e-6);
}

TEST(InterfaceStrength, RefusesMOutsideZeroOneAndNoYieldStrength)
{
  for (double m : {-0.01, 1.0000001, 2.0, std::nan("")})
    EXPECT_NE(message_of([&] { tribo::interface_shear_strength(m, 350e6); })
                  .find("m: interface friction factor must be in [0, 1] (tau_s / (S_y / sqrt(3)) of the softer body)"),
              std::string::npos)
        << m;
  EXPECT_EQ(message_of([] { tribo::interface_shear_strength(0.5, 0.0); }),
            "S_y: tau_s = m S_y / sqrt(3) needs the yield strength of the softer body, got 0");
}

TEST(InterfaceStrength, AnInterfaceStrongerThanTheSofterBodyIsRefused)
{
  const double k = 350e6 * kInvSqrt3;
  EXPECT_NO_THROW(tribo::check_interface_strength(k * (1.0 - 1e-12), 350e6));
  EXPECT_NO_THROW(tribo::check_interface_strength(0.0, 350e6));
  EXPECT_EQ(message_of([] { tribo::check_interface_strength(2.5e8, 350e6); }),
            "tau_s: interfacial shear strength 2.5e+08 Pa exceeds the shear yield strength of the softer body, "
            "S_y / sqrt(3) = 2.02073e+08 Pa (S_y = 3.5e+08 Pa): an interface cannot be stronger than the body under "
            "it; lower tau_s");
}

TEST(InterfaceStrength, StatesByNameAndUnknownOnesListTheKnown)
{
  EXPECT_EQ(tribo::find_interface_state("clean"), 0);
  EXPECT_EQ(tribo::find_interface_state("oxidised"), 1);
  EXPECT_EQ(tribo::find_interface_state("boundary"), 2);
  EXPECT_EQ(error_of([] { tribo::find_interface_state("wet"); }),
            "interface: unknown interface state 'wet' (known: clean, oxidised, boundary)");
}

TEST(InterfaceStrength, FileLinesInEitherOrderAndMissingStatesAreNaN)
{
  const auto file = parse(kGood + "interface Cu Al oxidised 0.885\ninterface Al Cu boundary 0.1\n");
  for (const auto &entry : {file.pair("Cu", "Al"), file.pair("Al", "Cu")}) {
    EXPECT_TRUE(std::isnan(entry.interface_factor[0]));
    EXPECT_EQ(entry.interface_factor[1], 0.885);
    EXPECT_EQ(entry.interface_factor[2], 0.1);
  }
  for (double m : parse(kGood).pair("Cu", "Al").interface_factor) EXPECT_TRUE(std::isnan(m));
}

TEST(InterfaceStrength, BadFileLinesNameFileLineAndEntry)
{
  auto error = [](const std::string &text) { return message_of([&] { parse(text); }); };
  EXPECT_EQ(error(kGood + "interface Cu Al clean 1.5\n"),
            "x.runin line 4: interface Cu Al clean: m must be in [0, 1] (tau_s / (S_y / sqrt(3)) of the softer body), "
            "got '1.5'");
  EXPECT_EQ(error(kGood + "interface Cu Al clean -0.1\n"),
            "x.runin line 4: interface Cu Al clean: m must be in [0, 1] (tau_s / (S_y / sqrt(3)) of the softer body), "
            "got '-0.1'");
  EXPECT_EQ(error(kGood + "interface Cu Al clean 1e999\n"),
            "x.runin line 4: interface Cu Al clean: m must be a finite number, got '1e999'");
  EXPECT_EQ(error(kGood + "interface Cu Al wet 0.5\n"),
            "x.runin line 4: interface: unknown interface state 'wet' (known: clean, oxidised, boundary)");
  EXPECT_EQ(error(kGood + "interface Cu Al 0.5\n"),
            "x.runin line 4: interface needs A B STATE m (STATE: clean, oxidised, boundary)");
  EXPECT_EQ(error(kGood + "interface Cu Al clean 0.9\ninterface Al Cu clean 0.8\n"),
            "x.runin line 5: interface Al Cu clean: given twice");
}

// tau_s = m S_y / sqrt(3) for the adhesion laws, f = m for junction; the other combinations refused by name.
TEST(InterfaceStrength, ContactCoefficientsTakeTheStatesFactor)
{
  for (const char *friction : {"strength", "brizmer"})
    for (int state = 0; state < tribo::kInterfaceStates; ++state) {
      tribo::ContactParameters p = steel();
      p.interface_state = state;
      const auto c = tribo::contact_coefficients(choice("elastic/plastic", friction), p);
      EXPECT_NEAR(tau_s_of(c, friction), p.interface_factors[state] * 350e6 * kInvSqrt3, 1e-6) << friction << state;
      EXPECT_NO_THROW(tribo::ContactModel(choice("elastic/plastic", friction), c, {}));
    }
  // the boundary state of AISI 1020: the 20 MPa boundary film of the homogenisation decks
  tribo::ContactParameters p = steel();
  p.interface_state = 2;
  EXPECT_NEAR(tau_s_of(tribo::contact_coefficients(choice("hertz", "strength"), p), "strength"), 20.207e6, 1e3);

  p = steel();
  p.interface_state = 1;
  EXPECT_EQ(tribo::contact_coefficients(choice("elastic/plastic", "junction"), p).of(SubModelKind::friction)[0], 0.8921);
  p.interface_state = 0;    // m = 1: junction refuses f = 1 (seizure)
  EXPECT_NE(message_of([&] {
              tribo::ContactModel(choice("elastic/plastic", "junction"),
                                  tribo::contact_coefficients(choice("elastic/plastic", "junction"), p), {});
            }).find("f: interface coefficient must be in [0, 1)"),
            std::string::npos);
}

TEST(InterfaceStrength, ContactCoefficientsRefuseStatesTheyCannotApply)
{
  auto error = [](tribo::ContactParameters p, const char *friction, const char *normal = "elastic/plastic") {
    return message_of([&] { tribo::contact_coefficients(choice(normal, friction), p); });
  };
  tribo::ContactParameters p = steel();
  p.interface_state = 1;
  EXPECT_EQ(error(p, "coulomb"), "interface: friction model 'coulomb' has no interface strength (interface oxidised "
                                 "sets tau_s of 'strength' and 'brizmer' or f of 'junction')");
  tribo::ContactParameters both = p;
  both.shear_strength = 2e7;
  EXPECT_EQ(error(both, "strength"), "interface: give either tau_s or interface oxidised, not both");
  both = p;
  both.interface_coefficient = 0.5;
  EXPECT_EQ(error(both, "junction"), "interface: give either f or interface oxidised, not both");
  tribo::ContactParameters missing = p;
  missing.interface_factors = tribo::no_interface_factors();
  EXPECT_EQ(error(missing, "strength"),
            "interface: no friction factor m for state 'oxidised' of this material pair (a coefficient file line "
            "'interface A B oxidised m'; the file form reads it)");
  tribo::ContactParameters guessed = p;
  guessed.yield_from_hardness = true;
  EXPECT_NE(error(guessed, "strength").find("interface: tau_s = m S_y / sqrt(3) needs the yield strength of the softer "
                                            "body, not Tabor's H / 2.8"),
            std::string::npos);
}

// An explicit tau_s above S_y / sqrt(3) of a known S_y is refused with either normal model; with Tabor's H / 2.8
// guess the earlier behaviour stays (only the hardness bounds tau_s), and above the hardness ContactModel's
// message comes first.
TEST(InterfaceStrength, ExplicitShearStrengthAboveTheSofterBodysShearYield)
{
  for (const char *normal : {"hertz", "elastic/plastic"})
    for (const char *friction : {"strength", "brizmer"}) {
      if (std::string(normal) == "hertz" && std::string(friction) == "brizmer") continue;
      tribo::ContactParameters p = steel();
      p.shear_strength = 2.03e8;
      EXPECT_NE(message_of([&] { tribo::contact_coefficients(choice(normal, friction), p); })
                    .find("tau_s: interfacial shear strength 2.03e+08 Pa exceeds the shear yield strength of the "
                          "softer body, S_y / sqrt(3) = 2.02073e+08 Pa"),
                std::string::npos)
          << normal << " " << friction;
      p.shear_strength = 2.02e8;
      EXPECT_NO_THROW(tribo::contact_coefficients(choice(normal, friction), p)) << normal << " " << friction;
      p.shear_strength = 2.03e8;
      p.yield_from_hardness = true;
      EXPECT_NO_THROW(tribo::contact_coefficients(choice(normal, friction), p)) << normal << " " << friction;
    }
  tribo::ContactParameters p = steel();
  p.shear_strength = 1e308;
  EXPECT_NO_THROW(tribo::contact_coefficients(choice("hertz", "strength"), p));
}

// The shipped files: every state line parses; the oxidised m reproduces the file's dry mu_k through Tabor's
// closed form at alpha = 12 (how it was derived, doc/interface_strength.md); boundary and clean as cited.
TEST(InterfaceStrength, ShippedFilesStates)
{
  struct Shipped {
    const char *file, *a, *b;
  };
  for (const Shipped &s : {Shipped{"Steel1020.runin", "Steel1020", "Steel1020"}, Shipped{"CuAl.runin", "Cu", "Al"},
                           Shipped{"GreyCastIron.runin", "GreyCastIron", "GreyCastIron"}}) {
    const std::string path = std::string(RUNIN_SOURCE_DIR) + "/potentials/" + s.file;
    std::ifstream in(path);
    ASSERT_TRUE(in) << path;
    const auto entry = tribo::parse_material_file(in, path).pair(s.a, s.b);
    const double clean = entry.interface_factor[0], oxidised = entry.interface_factor[1],
                 boundary = entry.interface_factor[2];
    EXPECT_EQ(clean, 1.0) << path;
    EXPECT_EQ(boundary, 0.1) << path;
    const double alpha = tribo::JunctionFrictionModel::kDefaultAlpha;
    const double tabor = oxidised / std::sqrt(alpha * (1.0 - oxidised * oxidised));
    EXPECT_NEAR(tabor, entry.mu_kinetic, 1e-3 * entry.mu_kinetic) << path;
    EXPECT_TRUE(boundary < oxidised && oxidised < clean) << path;
  }
}
