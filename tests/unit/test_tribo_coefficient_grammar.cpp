// The coefficient grammar (plugins/common/coefficient_grammar.h) on a host adaptor of its own: the hosts' parser
// without a host. The LAMMPS and LIGGGHTS adaptors are checked through their pair_coeff (PAIR_COEFF_BAD_ROWS,
// tests/lammps/CMakeLists.txt); here the forms, Tabor's fallback and the messages themselves.
#include "coefficient_test_host.h"

#include <gtest/gtest.h>

#include <string>

namespace {

namespace tribo = runin::tribo;
using runin_test::choice_of;
using runin_test::Failed;
using runin_test::Words;
using TestHost = runin_test::CoefficientTestHost;

tribo::ContactCoefficients pair_coeff(TestHost &t, const std::string &line, tribo::ContactModelChoice choice)
{
  Words w(line);
  return runin_coeff::pair_coeff(t.host, w.narg(), w.arg.data(), choice, tribo::ContactSettings());
}

std::string error_of(TestHost &t, const std::string &line, tribo::ContactModelChoice choice)
{
  try {
    pair_coeff(t, line, choice);
  } catch (const Failed &e) {
    return e.what();
  }
  return "accepted";
}

}    // namespace

// The explicit form with its options and the keyword block with the same numbers are the same coefficients.
TEST(CoefficientGrammar, ExplicitFormAndKeywordBlockGiveTheSameCoefficients)
{
  TestHost t(true);
  const auto choice = choice_of("elastic/plastic", "strength");
  const auto explicit_form =
      pair_coeff(t, "1 1 1.092e11 4.3e10 0.8 0.5 0.4 2.0e-8 1.0e-3 1.19e9 S_y 3.5e8 nu 0.29 tau_s 1.0e8 plough 1.0", choice);
  const auto block = pair_coeff(t,
                                "1 1 normal elastic/plastic 1.092e11 3.5e8 0.29 damping restitution 0.8 tangential "
                                "mindlin 4.3e10 friction strength 0.5 0.4 2.0e-8 1.0e8 1.0 wear archard 1.0e-3 "
                                "1.19e9 1.0e-3 1.19e9",
                                choice);
  for (int k = 0; k < tribo::kSubModelKinds; ++k) EXPECT_EQ(explicit_form.values[k], block.values[k]) << "kind " << k;
  EXPECT_TRUE(t.warnings.empty());
}

// Without S_y the explicit form takes Tabor's H / 2.8 and says so once; the keyword block names S_y itself.
TEST(CoefficientGrammar, TaborsFallbackAndItsOneWarning)
{
  TestHost t(true);
  const auto choice = choice_of("elastic/plastic", "coulomb");
  const auto c = pair_coeff(t, "1 1 1.092e11 4.3e10 0.8 0.5 0.4 2.0e-8 1.0e-3 1.19e9", choice);
  EXPECT_EQ(c.of(tribo::SubModelKind::normal)[1], 1.19e9 / 2.8);
  ASSERT_EQ(t.warnings.size(), 1u);
  EXPECT_EQ(t.warnings[0], "pair_coeff runin/asperity 1 1: no yield strength given (S_y keyword or material file): "
                           "S_y = H / 2.8 = 4.25e+08 Pa (Tabor), nu = 0.3");
  // Hertz summits do not yield: no WARNING
  pair_coeff(t, "1 1 1.092e11 4.3e10 0.8 0.5 0.4 2.0e-8 1.0e-3 1.19e9", choice_of("hertz", "coulomb"));
  EXPECT_EQ(t.warnings.size(), 1u);
}

// tau_s is found by its registry name in any friction model that has it: the block's check against S_y / sqrt(3).
TEST(CoefficientGrammar, KeywordBlockTauSAgainstItsYieldStrength)
{
  TestHost t(true);
  const std::string block = "1 1 normal elastic/plastic 1.092e11 3.5e8 0.29 damping restitution 0.5 tangential "
                            "mindlin 4.3e10 friction brizmer 2.0e-8 2.1e8 1.0 wear archard 0 1e9 0 1e9";
  EXPECT_EQ(error_of(t, block, choice_of("elastic/plastic", "brizmer")).rfind(
                "pair_coeff runin/asperity (keywords): tau_s: interfacial shear strength 2.1e+08 Pa exceeds the shear "
                "yield strength of the softer body", 0),
            0u);
}

// The messages name the argument; a host without a film (LIGGGHTS) lists no film keywords, the rest is the same.
TEST(CoefficientGrammar, BadInputIsOneMessageNamingTheArgument)
{
  TestHost lammps(true), liggghts(false);
  const auto coulomb = choice_of("hertz", "coulomb");
  for (TestHost *t : {&lammps, &liggghts}) {
    EXPECT_EQ(error_of(*t, "1 1 normal hertz 4.8e10 damping restitution 0.5 damping restitution 0.5", coulomb),
              "pair_coeff runin/asperity: the damping block is given twice");
    EXPECT_EQ(error_of(*t, "1 1 normal hertz 4.8e10 1e9", coulomb),
              "pair_coeff runin/asperity: normal model 'hertz' takes 1 coefficient(s) (E*), got 2");
    EXPECT_EQ(error_of(*t, "1 1 normal hertz 1e999", coulomb),
              "pair_coeff runin/asperity: normal hertz: E* must be a finite number, got '1e999'");
    EXPECT_EQ(error_of(*t, "1 1 4.8e10 1.9e10 0.5 0.95", coulomb).rfind(
                  "pair_coeff runin/asperity: expected 'I J E* G* e mu_s mu_k d_c k H' (8 values after the type pair), "
                  "got 4 value(s) (missing: mu_k d_c k H); or 'I J file", 0),
              0u);
    EXPECT_EQ(error_of(*t, "1 1 file potentials/CuAl.runin Cu", coulomb),
              "pair_coeff runin/asperity: 'file' takes a path and two material names ('I J file <path> <material-I> "
              "<material-J>'), got 2 value(s)");
  }
  const std::string unknown = "1 1 4.8e10 1.9e10 0.5 0.95 0.55 0.0 1.0e-3 0.245e9 adhesion 1.0e8";
  EXPECT_EQ(error_of(lammps, unknown, coulomb), "pair_coeff runin/asperity: unknown keyword 'adhesion' (expected tau_s, "
                                                "plough, S_y, nu, f, alpha, interface, f_film, s_r or k_g)");
  EXPECT_EQ(error_of(liggghts, unknown, coulomb),
            "pair_coeff runin/asperity: unknown keyword 'adhesion' (expected tau_s, plough, S_y, nu, f, alpha or interface)");
}
