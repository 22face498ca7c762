// tribo::parse_material_file: the one reader of potentials/*.runin (LAMMPS styles, LIGGGHTS host, CLI).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "tribo/contact_model.h"
#include "tribo/material_file.h"

using runin::tribo::InvalidCoefficient;
using runin::tribo::MaterialFileError;
using runin::tribo::parse_material_file;

namespace {

runin::tribo::MaterialFile parse(const std::string &text) {
  std::istringstream in(text);
  return parse_material_file(in, "x.runin");
}

std::string error_of(const std::string &text) {
  try {
    parse(text).pair("Cu", "Al");
  } catch (const std::exception &e) {
    return e.what();
  }
  return "";
}

const std::string kGood =
    "# comment\n"
    "material Cu  110.0e9  0.37  8960.0  0.87e9   250.0e6   # trailing comment\n"
    "material Al   69.0e9  0.33  2700.0  0.245e9\n"
    "\n"
    "pair Al Cu  0.5  0.95  0.55  2.0e-8  1.0e-3\n";

}  // namespace

TEST(MaterialFile, ReadsMaterialsAndThePairInEitherOrder) {
  const auto file = parse(kGood);
  const auto cu_al = file.pair("Cu", "Al"), al_cu = file.pair("Al", "Cu");
  EXPECT_EQ(cu_al.a.youngs_modulus, 110.0e9);
  EXPECT_EQ(cu_al.a.poisson_ratio, 0.37);
  EXPECT_EQ(cu_al.a.hardness, 0.87e9);
  EXPECT_EQ(cu_al.a.yield_strength, 250.0e6);
  EXPECT_EQ(cu_al.b.youngs_modulus, 69.0e9);
  EXPECT_EQ(cu_al.b.yield_strength, 0.0);  // not given: the hosts fall back to H / 2.8 and say so
  EXPECT_EQ(al_cu.a.youngs_modulus, 69.0e9);
  for (const auto &p : {cu_al, al_cu}) {
    EXPECT_EQ(p.restitution, 0.5);
    EXPECT_EQ(p.mu_static, 0.95);
    EXPECT_EQ(p.mu_kinetic, 0.55);
    EXPECT_EQ(p.slip_weakening_distance, 2.0e-8);
    EXPECT_EQ(p.wear_coefficient, 1.0e-3);
  }
}

TEST(MaterialFile, EveryShippedFileParses) {
  for (const char *name : {"CuAl.runin", "Steel1020.runin", "GreyCastIron.runin"}) {
    const std::string path = std::string(RUNIN_SOURCE_DIR) + "/potentials/" + name;
    std::ifstream in(path);
    ASSERT_TRUE(in) << path;
    const auto file = parse_material_file(in, path);
    EXPECT_FALSE(file.materials.empty()) << path;
    EXPECT_FALSE(file.pairs.empty()) << path;
    for (const auto &[names, entry] : file.pairs) EXPECT_NO_THROW(file.pair(names.first, names.second)) << path;
  }
}

TEST(MaterialFile, NonFiniteOrWordsAreNamedByLineAndEntry) {
  EXPECT_EQ(error_of("material Cu 1e999 0.37 8960 0.87e9\n"),
            "x.runin line 1: material Cu: E must be a finite number, got '1e999'");
  EXPECT_EQ(error_of(kGood + "material Zn 9e10 nan 7000 1e9\n"),
            "x.runin line 6: material Zn: nu must be a finite number, got 'nan'");
  EXPECT_EQ(error_of(kGood + "pair Cu Zn 0.5 abc 0.5 1e-8 1e-3\n"),
            "x.runin line 6: pair Cu Zn: mu_s must be a finite number, got 'abc'");
  EXPECT_EQ(error_of("material Cu 0x10 0.37 8960 0.87e9\n"),
            "x.runin line 1: material Cu: E must be a finite number, got '0x10'");
}

TEST(MaterialFile, MalformedLinesAndMissingEntries) {
  EXPECT_EQ(error_of("material Cu 1e11 0.37\n"), "x.runin line 1: material needs NAME E nu rho H [S_y]");
  EXPECT_EQ(error_of("pair Cu Al 0.5 0.9\n"), "x.runin line 1: pair needs A B e mu_s mu_k d_c k");
  EXPECT_EQ(error_of("lubricant oil 1\n"), "x.runin line 1: unknown entry 'lubricant'");
  EXPECT_EQ(error_of("material Cu 110e9 0.37 8960 0.87e9 -1\n"), "x.runin line 1: material Cu: S_y must be > 0");
  EXPECT_EQ(error_of("material Cu 110e9 0.37 8960 0.87e9\n"), "x.runin: no material 'Al'");
  EXPECT_EQ(error_of("material Cu 110e9 0.37 8960 0.87e9\nmaterial Al 69e9 0.33 2700 0.245e9\n"),
            "x.runin: no 'pair Cu Al' entry");
}

TEST(MaterialFile, ImpossibleValuesThrowTheMaterialsOwnCheck) {
  std::istringstream in("material Cu -1e9 0.37 8960 0.87e9\n");
  EXPECT_THROW(parse_material_file(in, "x.runin"), InvalidCoefficient);
  EXPECT_EQ(error_of("material Cu 110e9 0.37 8960 -3e9\n"), "x.runin line 1: material Cu: hardness must be > 0");
}
