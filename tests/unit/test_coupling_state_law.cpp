// State law tables: interpolation (linear in h, power law in p where positive, linear in ln p
// otherwise), the range policies, JSON round trip and the checks on a malformed file.
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/ave_time_reader.h"
#include "coupling/scale_separation.h"
#include "coupling/state_law.h"

using namespace runin::coupling;

namespace {

// mu = (0.3 - 1e5 h) (p / 1 MPa)^-0.4: linear in h, a power of p, so interpolation must be exact.
double mu_exact(double p, double h) { return (0.3 - 1e5 * h) * std::pow(p / 1e6, -0.4); }
// rsk = -1 + 0.2 ln(p / 1 MPa) - 1e6 h: negative, so linear in (ln p, h), exact as well.
double rsk_exact(double p, double h) { return -1.0 + 0.2 * std::log(p / 1e6) - 1e6 * h; }

StateLaw make_law(bool band = true) {
  const std::vector<double> p = {1e6, 1e7, 1e8}, h = {0.0, 1e-7, 2e-7};
  std::array<StateFieldTable, state_field_count> fields;
  for (std::size_t f = 0; f < state_field_count; ++f) {
    auto &t = fields[f];
    t.mean.assign(p.size(), std::vector<double>(h.size()));
    for (std::size_t i = 0; i < p.size(); ++i)
      for (std::size_t j = 0; j < h.size(); ++j)
        t.mean[i][j] = static_cast<StateField>(f) == StateField::Rsk ? rsk_exact(p[i], h[j]) : mu_exact(p[i], h[j]) * (1 + f);
    if (band) {
      t.low = t.mean;
      t.high = t.mean;
      for (auto &row : t.low)
        for (double &x : row) x -= 0.01;
      for (auto &row : t.high)
        for (double &x : row) x += 0.02;
    }
  }
  return StateLaw(p, h, fields, {{"material", "Steel1020/Steel1020"}});
}

}  // namespace

TEST(StateLaw, PowerLawInPressureLinearInDepthIsExact) {
  const auto law = make_law(false);
  for (double p : {1e6, 2.5e6, 3.3e7, 1e8})
    for (double h : {0.0, 3e-8, 1.5e-7, 2e-7}) {
      EXPECT_NEAR(law.value(StateField::MuBody, p, h), mu_exact(p, h), 1e-14) << p << " " << h;
      EXPECT_NEAR(law.value(StateField::Rsk, p, h), rsk_exact(p, h), 1e-12) << p << " " << h;
    }
  const auto v = law.values(4e6, 5e-8);
  EXPECT_NEAR(v.mu_body, mu_exact(4e6, 5e-8), 1e-14);
  EXPECT_NEAR(v.wear_rate, mu_exact(4e6, 5e-8) * 5, 1e-13);
  EXPECT_NEAR(v.rsk, rsk_exact(4e6, 5e-8), 1e-12);
  // at the geometric midpoint of a grid step the power law is the geometric mean, not the arithmetic one
  EXPECT_NEAR(law.value(StateField::MuBody, std::sqrt(1e6 * 1e7), 0.0),
              std::sqrt(mu_exact(1e6, 0.0) * mu_exact(1e7, 0.0)), 1e-14);
}

TEST(StateLaw, BandsInterpolateLikeTheMean) {
  const auto law = make_law();
  const double p = 4e6, h = 5e-8;
  const double lo0 = mu_exact(1e6, h) - 0.01, lo1 = mu_exact(1e7, h) - 0.01;
  const double w = std::log(p / 1e6) / std::log(10.0);
  EXPECT_NEAR(law.value(StateField::MuBody, p, h, Band::Low), lo0 * std::pow(lo1 / lo0, w), 1e-14);
  const double hi0 = mu_exact(1e6, h) + 0.02, hi1 = mu_exact(1e7, h) + 0.02;
  EXPECT_NEAR(law.value(StateField::MuBody, p, h, Band::High), hi0 * std::pow(hi1 / hi0, w), 1e-14);
}

TEST(StateLaw, DepthBeyondTheGridHoldsTheLastRowAndIsCounted) {
  const auto law = make_law();
  RangeUse use;
  EXPECT_NEAR(law.value(StateField::MuBody, 1e7, 5e-7, Band::Mean, OutOfRange::Error, &use), mu_exact(1e7, 2e-7),
              1e-14);
  EXPECT_EQ(use.beyond_depth, 1);
  EXPECT_EQ(use.lookups, 1);
}

TEST(StateLaw, PressureOutsideIsAnErrorOrACountedClamp) {
  const auto law = make_law();
  EXPECT_THROW(law.value(StateField::MuBody, 5e5, 0.0), std::out_of_range);
  EXPECT_THROW(law.value(StateField::MuBody, 2e8, 0.0), std::out_of_range);
  EXPECT_THROW(law.value(StateField::MuBody, std::nan(""), 0.0), std::out_of_range);
  EXPECT_THROW(law.value(StateField::MuBody, 1e7, std::nan("")), std::out_of_range);
  RangeUse use;
  EXPECT_NEAR(law.value(StateField::MuBody, 5e5, 0.0, Band::Mean, OutOfRange::Clamp, &use), mu_exact(1e6, 0.0),
              1e-12);
  EXPECT_NEAR(law.value(StateField::MuBody, 2e8, 0.0, Band::Mean, OutOfRange::Clamp, &use), mu_exact(1e8, 0.0),
              1e-12);
  EXPECT_EQ(use.below_pressure, 1);
  EXPECT_EQ(use.above_pressure, 1);
}

// Archard policy: friction and surface state as Clamp, wear rates and real area proportional to p outside the grid,
// through every read path (value, values, slice + wear_rates), counted like a clamp.
TEST(StateLaw, ArchardPolicyKeepsWearProportionalToPressureOutsideTheGrid) {
  const auto law = make_law();
  const double h = 5e-8;
  for (double p : {1e3, 5e5, 2e8, 1e9}) {
    const double edge = p < 1e6 ? 1e6 : 1e8;
    RangeUse use;
    const auto v = law.values(p, h, OutOfRange::Archard, &use);
    EXPECT_NEAR(v.mu_body, mu_exact(edge, h), 1e-14) << p;
    EXPECT_NEAR(v.rsk, rsk_exact(edge, h), 1e-12) << p;
    EXPECT_NEAR(v.rq, mu_exact(edge, h) * 2, 1e-13) << p;
    EXPECT_NEAR(v.wear_rate / p, mu_exact(edge, h) * 5 / edge, 1e-12 * mu_exact(edge, h) * 5 / edge) << p;
    EXPECT_NEAR(v.counterface_wear_rate / p, mu_exact(edge, h) * 6 / edge, 1e-12 * mu_exact(edge, h) * 6 / edge);
    EXPECT_NEAR(v.area_fraction / p, mu_exact(edge, h) * 4 / edge, 1e-12 * mu_exact(edge, h) * 4 / edge);
    const auto slice = law.slice(p, OutOfRange::Archard);
    double w = 0.0, wc = 0.0;
    law.wear_rates(slice, h, &use, w, wc);
    EXPECT_DOUBLE_EQ(w, v.wear_rate);
    EXPECT_DOUBLE_EQ(wc, v.counterface_wear_rate);
    EXPECT_DOUBLE_EQ(law.value(StateField::WearRate, slice, h), v.wear_rate);
    EXPECT_DOUBLE_EQ(law.value(StateField::WearRate, p, h, Band::Mean, OutOfRange::Archard), v.wear_rate);
    EXPECT_DOUBLE_EQ(law.value(StateField::MuBody, slice, h), v.mu_body);
    EXPECT_EQ(use.lookups, 2);
    EXPECT_EQ(p < 1e6 ? use.below_pressure : use.above_pressure, 2);
  }
  // inside the grid the policy changes nothing
  const auto inside = law.values(4e6, h, OutOfRange::Archard);
  EXPECT_DOUBLE_EQ(inside.wear_rate, law.values(4e6, h).wear_rate);
  EXPECT_STREQ(to_string(OutOfRange::Archard), "archard");
}

TEST(StateLaw, JsonRoundTripKeepsTablesAndMetadata) {
  const auto law = make_law();
  const auto back = StateLaw::from_json(law.to_json(), "law.json");
  EXPECT_EQ(back.pressure(), law.pressure());
  EXPECT_EQ(back.worn_depth(), law.worn_depth());
  EXPECT_TRUE(back.has_band());
  EXPECT_EQ(back.metadata().at("material"), "Steel1020/Steel1020");
  EXPECT_DOUBLE_EQ(back.value(StateField::Rsk, 2e6, 1e-7), law.value(StateField::Rsk, 2e6, 1e-7));
  EXPECT_FALSE(StateLaw::from_json(make_law(false).to_json(), "x").has_band());
}

// The bodies' materials for the elements' check: material.rough / .counterface as homogenise writes them; a law
// whose material is no such object (a string, a synthetic law) names none.
TEST(StateLaw, MaterialsFromTheMetadata) {
  EXPECT_FALSE(make_law().materials());  // "Steel1020/Steel1020": a string, not homogenise's object
  auto document = make_law().to_json();
  document["material"] = {{"rough", "Cu"}, {"counterface", "Al"}, {"file", "potentials/CuAl.runin"}};
  const auto pair = StateLaw::from_json(document, "law.json").materials();
  ASSERT_TRUE(pair);
  EXPECT_EQ(pair->first, "Cu");
  EXPECT_EQ(pair->second, "Al");
  document["material"] = {{"rough", "Cu"}};
  EXPECT_FALSE(StateLaw::from_json(document, "law.json").materials());
}

TEST(StateLaw, MalformedFilesGiveOneLineNamingTheKey) {
  const auto good = make_law().to_json();
  auto expect_error = [](nlohmann::json doc, const std::string &needle) {
    try {
      StateLaw::from_json(doc, "law.json");
      ADD_FAILURE() << "no error for " << needle;
    } catch (const InputFormatError &e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("law.json: state law: "), std::string::npos) << what;
      EXPECT_NE(what.find(needle), std::string::npos) << what;
      EXPECT_EQ(what.find('\n'), std::string::npos) << what;
    }
  };
  auto doc = good;
  doc["format"] = "something";
  expect_error(doc, "format");
  doc = good;
  doc["version"] = 2;
  expect_error(doc, "version");
  doc = good;
  doc.erase("fields");
  expect_error(doc, "fields");
  doc = good;
  doc["pressure"] = {1e7, 1e6, 1e8};
  expect_error(doc, "pressure");
  doc = good;
  doc["worn_depth"] = {1e-9, 1e-7, 2e-7};
  expect_error(doc, "worn_depth");
  doc = good;
  doc["fields"]["mu_body"]["mean"][1] = {0.1, 0.2};
  expect_error(doc, "mu_body.mean");
  doc = good;
  doc["fields"]["wear_rate"]["mean"][0][0] = -1.0;
  expect_error(doc, "wear_rate.mean");
  doc = good;
  doc["fields"]["rq"]["low"][0][0] = 1e3;
  expect_error(doc, "rq: low <= mean <= high");
  doc = good;
  doc["fields"].erase("rsk");
  expect_error(doc, "rsk");
  doc = good;
  doc["fields"]["area_fraction"]["mean"][0][0] = "x";
  expect_error(doc, "area_fraction.mean");
}

// The homogenisation cell from the law's surface metadata, and the scale-separation criterion against it.
TEST(ScaleSeparation, CellFromTheLawsSurfaceAndTheThreeCellCriterion) {
  const auto base = make_law(false);
  EXPECT_FALSE(cell_scale(base).has_value());  // a synthetic law names no cell
  auto json = base.to_json();
  json["surface"] = {{"nside", 48}, {"spacing", 2e-5}, {"summits", 2304}, {"R", 1e-4}};
  const auto law = StateLaw::from_json(json, "law.json");
  const auto cell = cell_scale(law);
  ASSERT_TRUE(cell.has_value());
  EXPECT_DOUBLE_EQ(cell->cell_size, 48 * 2e-5);
  EXPECT_NEAR(cell->summit_density, 1.0 / (2e-5 * 2e-5), 1e-6 / (2e-5 * 2e-5));
  const ScaleSeparation narrow{*cell, 0.35e-3, 58.6e-6 * 25e-3};
  EXPECT_FALSE(narrow.holds());
  EXPECT_NEAR(narrow.cells_across(), 0.35e-3 / 0.96e-3, 1e-12);
  EXPECT_NEAR(narrow.summits_per_node(), 58.6e-6 * 25e-3 / 4e-10, 1e-6);
  EXPECT_NE(scale_separation_warning(narrow).find("no scale separation"), std::string::npos);
  const ScaleSeparation wide{*cell, 3 * 0.96e-3, 1e-6};
  EXPECT_TRUE(wide.holds());
  EXPECT_TRUE(scale_separation_warning(wide).empty());
  EXPECT_NE(describe(wide).find("holds"), std::string::npos);
}
