// Patir & Cheng flow factors against their published fits (coefficients of the 1978 and 1979 tables),
// each expected value evaluated by hand from the fit formula as printed.
#include "tribo/contact.h"
#include "tribo/flow_factors.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace runin::tribo;

TEST(FlowFactors, PressureFlowFactorsMatchPatirChengFits)
{
  // gamma = 1: phi_x = 1 - 0.90 exp(-0.56 H)
  EXPECT_NEAR(pressure_flow_factor_x(1.0, 1.0), 1.0 - 0.90 * std::exp(-0.56), 1e-12);
  EXPECT_NEAR(pressure_flow_factor_x(1.0, 1.0), 0.4859, 5e-5);
  EXPECT_NEAR(pressure_flow_factor_x(3.0, 1.0), 0.8323, 5e-5);
  EXPECT_NEAR(pressure_flow_factor_x(6.0, 1.0), 0.9687, 5e-5);
  // gamma = 1/9: 1 - 1.48 exp(-0.42 H); gamma = 9: 1 + 0.870 H^-1.5; gamma = 3: 1 + 0.225 H^-1.5
  EXPECT_NEAR(pressure_flow_factor_x(2.0, 1.0 / 9.0), 0.3611, 5e-5);
  EXPECT_NEAR(pressure_flow_factor_x(2.0, 9.0), 1.3076, 5e-5);
  EXPECT_NEAR(pressure_flow_factor_x(2.0, 3.0), 1.0795, 5e-5);
  // phi_y(gamma) = phi_x(1/gamma); isotropic: equal
  EXPECT_DOUBLE_EQ(pressure_flow_factor_y(2.0, 1.0 / 9.0), pressure_flow_factor_x(2.0, 9.0));
  EXPECT_DOUBLE_EQ(pressure_flow_factor_y(2.0, 1.0), pressure_flow_factor_x(2.0, 1.0));
  // smooth limit
  EXPECT_NEAR(pressure_flow_factor_x(40.0, 1.0), 1.0, 1e-9);
  EXPECT_NEAR(pressure_flow_factor_x(400.0, 9.0), 1.0, 1e-3);
  // between table points: linear in ln gamma, bounded by the neighbours
  const double mid = pressure_flow_factor_x(2.0, std::sqrt(3.0 * 6.0));
  EXPECT_NEAR(mid, 0.5 * (pressure_flow_factor_x(2.0, 3.0) + pressure_flow_factor_x(2.0, 6.0)), 1e-12);
  // below H = 0.5 the fit is held at 0.5
  EXPECT_DOUBLE_EQ(pressure_flow_factor_x(0.1, 1.0), pressure_flow_factor_x(0.5, 1.0));
}

TEST(FlowFactors, ShearFlowAndStressFactorsMatchPatirChengFits)
{
  // gamma = 1: Phi_s = 1.899 H^0.98 exp(-0.92 H + 0.05 H^2) (H <= 5), 1.126 exp(-0.25 H) (H > 5)
  EXPECT_NEAR(shear_flow_factor(1.0, 1.0), 0.7956, 5e-5);
  EXPECT_NEAR(shear_flow_factor(6.0, 1.0), 0.2512, 5e-5);
  // gamma = 3: 1.560 H^0.85 exp(-1.13 H + 0.08 H^2)
  EXPECT_NEAR(shear_flow_factor(2.0, 3.0), 0.4041, 5e-5);
  // the pair: equal roughness cancels, only the moving surface rough: +Phi_s
  EXPECT_DOUBLE_EQ(shear_flow_factor_pair(2.0, 1.0, 1e-6, 1e-6), 0.0);
  EXPECT_DOUBLE_EQ(shear_flow_factor_pair(2.0, 1.0, 1e-6, 0.0), shear_flow_factor(2.0, 1.0));
  EXPECT_DOUBLE_EQ(shear_flow_factor_pair(2.0, 1.0, 0.0, 1e-6), -shear_flow_factor(2.0, 1.0));
  // shear stress factors, gamma = 1: phi_fp = 1 - 1.40 exp(-0.66 H), phi_fs = 11.1 H^2.31 exp(-2.38 H + 0.11 H^2)
  EXPECT_NEAR(shear_stress_factor_fp(2.0, 1.0), 0.6260, 5e-5);
  EXPECT_NEAR(shear_stress_factor_fs(2.0, 1.0), 0.7321, 5e-5);
  EXPECT_DOUBLE_EQ(shear_stress_factor_fs(8.0, 1.0), 0.0);
  // phi_f: closed form for Gaussian heights; 7/6 at H = 3 from both branches, -> 1 + 1/H^2 for thick films
  EXPECT_NEAR(shear_stress_factor_f(4.0), 1.07495, 5e-6);
  EXPECT_NEAR(shear_stress_factor_f(3.0 - 1e-9), 7.0 / 6.0, 1e-6);
  EXPECT_NEAR(shear_stress_factor_f(3.0 + 1e-9), 7.0 / 6.0, 1e-6);
  EXPECT_NEAR(shear_stress_factor_f(30.0), 1.0011141531, 1e-9);   // 50-digit evaluation of the closed form
  EXPECT_NEAR(shear_stress_factor_f(30.0 - 1e-9), shear_stress_factor_f(30.0 + 1e-9), 1e-9);   // closed form | series
  EXPECT_NEAR(shear_stress_factor_f(90.0), 1.000123494217, 1e-12);   // 50-digit evaluation of the closed form
}

TEST(FlowFactors, MeanGapAndContactFactor)
{
  const double sigma = 1e-6;
  EXPECT_NEAR(mean_gap(0.0, sigma), sigma / std::sqrt(2.0 * std::acos(-1.0)), 1e-18);
  EXPECT_NEAR(mean_gap(6.0 * sigma, sigma), 6.0 * sigma, 1e-14);
  EXPECT_DOUBLE_EQ(mean_gap(2e-6, 0.0), 2e-6);
  EXPECT_NEAR(contact_factor(0.0), 0.5, 1e-15);
  const double dh = 1e-4 * sigma;   // contact factor = d h_T / d h
  EXPECT_NEAR((mean_gap(sigma + dh, sigma) - mean_gap(sigma - dh, sigma)) / (2.0 * dh), contact_factor(1.0), 1e-8);
}

TEST(FlowFactors, BadInputNamesTheField)
{
  try {
    pressure_flow_factor_x(1.0, 20.0);
    FAIL() << "no exception";
  } catch (const InvalidCoefficient &e) {
    EXPECT_NE(std::string(e.what()).find("gamma"), std::string::npos);
  }
  EXPECT_THROW(mean_gap(1e-6, -1e-7), InvalidCoefficient);
  EXPECT_THROW(pressure_flow_factor_x(std::nan(""), 1.0), InvalidCoefficient);
}
