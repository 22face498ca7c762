#include "cli/line_stress_report.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include <fmt/core.h>

namespace runin::cli {

tribo::Material verdict_material(const tribo::Material &m) {
  tribo::Material v = m;
  v.yield_strength = continuum::verdict_yield_strength(m);
  return v;
}

std::string body_label(const std::string &body, const std::string &material_name) {
  return material_name.empty() ? body : fmt::format("{} ({})", body, material_name);
}

#ifdef RUNIN_HAVE_VTK
coupling::SurfaceFrame section_frame(double time, const tribo::StressField &grid) {
  coupling::SurfaceFrame s;
  s.time = time;
  s.nu = static_cast<int>(grid.x.size());
  s.nv = static_cast<int>(grid.z.size());
  for (double z : grid.z)
    for (double x : grid.x) s.points.push_back({x, 0.0, -z});
  return s;
}
#endif

std::vector<std::string> write_line_stress(const LineStressReport &report, const std::filesystem::path &dir,
                                           const std::string &stem) {
#ifdef RUNIN_HAVE_VTK
  std::vector<coupling::SurfaceFrame> out;
  for (const auto &f : report.frames) {
    const auto &a = f.stress.a.field, &b = f.stress.b.field;
    coupling::SurfaceFrame s = section_frame(f.time, a);
    // The equivalent stresses only: the six components of both bodies would triple the files (and the
    // compression time); tribo::line_traction_field gives them on demand.
    const std::string &na = report.field_a, &nb = report.field_b;
    s.fields = {{"von_mises_" + na + "_Pa", a.von_mises()}, {"tresca_" + na + "_Pa", a.tresca()},
                {"von_mises_" + nb + "_Pa", b.von_mises()}, {"tresca_" + nb + "_Pa", b.tresca()}};
    out.push_back(std::move(s));
  }
  return coupling::write_surface_series(out, dir.string(), stem);
#else
  (void)report, (void)dir, (void)stem;
  return {};
#endif
}

void print_line_stress(const LineStressReport &report, std::vector<std::string> &warnings) {
  for (std::size_t i = 0; i < report.frames.size(); ++i) {
    const auto &f = report.frames[i].stress;
    const char *when = i == 0 ? "start" : "end";
    fmt::print("  subsurface stress {} {} (t = {:g} s): {}, p0 = {:.4g} Pa, b = {:.4g} m, mu = {:.3g}\n",
               report.contact, when, report.frames[i].time, f.method, f.peak_pressure, f.half_width,
               f.friction_coefficient);
    if (i == 0 && !report.cross_check.empty()) fmt::print("    {}\n", report.cross_check);
    for (const auto &[label, b, tabor] : {std::make_tuple(report.label_a, &f.a, report.tabor_a),
                                          std::make_tuple(report.label_b, &f.b, report.tabor_b)}) {
      const std::string verdict =
          b->yield_strength > 0.0
              ? fmt::format("S_y = {:.4g} Pa{}: {} (peak / S_y = {:.3g})", b->yield_strength,
                            tabor ? " (Tabor H / 2.8, no S_y in the file)" : "",
                            b->yields() ? "YIELDS" : "elastic", b->peak.von_mises / b->yield_strength)
              : fmt::format("S_y unknown (set {})", report.materials_hint);
      fmt::print("    {:<22} peak von Mises {:.4g} Pa at x = {:.3g} m, depth {:.3g} m (nu = {:.3g}); {}\n", label,
                 b->peak.von_mises, b->peak.x, b->peak.z, b->poisson_ratio, verdict);
      if (b->yields())
        warnings.push_back(fmt::format("WARNING: the {} yields below the {} at the {} of the run: peak von Mises "
                                       "{:.4g} Pa > S_y = {:.4g} Pa ({:.3g} x) at depth {:.3g} m; the elastic contact "
                                       "and wear model is outside its range there",
                                       label, report.contact, when, b->peak.von_mises, b->yield_strength,
                                       b->peak.von_mises / b->yield_strength, b->peak.z));
    }
  }
}

}  // namespace runin::cli
