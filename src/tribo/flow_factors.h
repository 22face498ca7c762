// Patir & Cheng average-flow factors for a Gaussian rough film (ASME J. Lubr. Technol. 100 (1978) 12-17:
// pressure flow; 101 (1979) 220-229: shear flow and shear stress), as their published curve fits.
// H = h / sigma: nominal gap (between the mean planes) over the combined rms roughness
// sigma = sqrt(sigma_1^2 + sigma_2^2). gamma: Peklenik surface pattern (ratio of the x and y correlation
// lengths; < 1 transverse ridges, 1 isotropic, > 1 longitudinal). The fits are tabulated at
// gamma = 1/9, 1/6, 1/3, 1, 3, 6, 9; between these the coefficients are interpolated linearly in ln gamma.
// The fits hold for H >= 0.5 (phi_x, phi_y, phi_fp) and H >= 0.5 .. 7 (phi_s, phi_fs): below 0.5 the
// factors are evaluated at H = 0.5 (the film is then mostly asperity contact and the flow terms small).
#pragma once

namespace runin::tribo {

constexpr double kFlowFactorMinH = 0.5;

// Pressure flow factors (1978):  phi_x = 1 - C exp(-r H) (gamma <= 1),  1 + C H^-r (gamma > 1);
// phi_y(H, gamma) = phi_x(H, 1 / gamma).
double pressure_flow_factor_x(double H, double gamma);
double pressure_flow_factor_y(double H, double gamma);

// Shear flow factor of ONE rough surface (1979): Phi_s = A1 H^a1 exp(-a2 H + a3 H^2) for H <= 5,
// A2 exp(-0.25 H) for H > 5. The film's phi_s = V_r1 Phi_s(gamma_1) - V_r2 Phi_s(gamma_2),
// V_ri = (sigma_i / sigma)^2 (shear_flow_factor_pair).
double shear_flow_factor(double H, double gamma);
double shear_flow_factor_pair(double H, double gamma, double sigma_moving, double sigma_fixed);

// Shear stress factors (1979): phi_f (Gaussian heights, closed form), phi_fp = 1 - D exp(-s H),
// phi_fs = A3 H^a4 exp(-a5 H + a6 H^2) for H <= 7 (0 beyond).
double shear_stress_factor_f(double H);
double shear_stress_factor_fp(double H, double gamma);
double shear_stress_factor_fs(double H, double gamma);

// Mean gap of a Gaussian rough film (Patir & Cheng 1978):
//   h_T = h/2 [1 + erf(H / sqrt 2)] + sigma / sqrt(2 pi) exp(-H^2 / 2)
// and its derivative dh_T/dh = [1 + erf(H / sqrt 2)] / 2 (the contact factor phi_c of the Couette term).
double mean_gap(double h, double sigma);
double contact_factor(double H);

}    // namespace runin::tribo
