#include "coupling/scale_separation.h"

#include <sstream>

namespace runin::coupling {

std::optional<CellScale> cell_scale(const StateLaw &law) {
  const auto &meta = law.metadata();
  if (!meta.contains("surface")) return std::nullopt;
  const auto &surface = meta.at("surface");
  if (!surface.contains("nside") || !surface.contains("spacing")) return std::nullopt;
  const double spacing = surface.at("spacing").get<double>();
  const double nside = surface.at("nside").get<double>();
  if (!(spacing > 0.0) || !(nside > 0.0)) return std::nullopt;
  CellScale cell;
  cell.cell_size = nside * spacing;
  const double summits = surface.contains("summits") ? surface.at("summits").get<double>() : nside * nside;
  cell.summit_density = summits / (cell.cell_size * cell.cell_size);
  return cell;
}

std::string describe(const ScaleSeparation &s) {
  std::ostringstream out;
  out.precision(4);
  out << "contact " << 1e3 * s.contact_width << " mm wide = " << s.cells_across() << " cells of "
      << 1e3 * s.cell.cell_size << " mm (" << (s.holds() ? "holds" : "fails") << ": at least " << kMinCellsAcross
      << "); smallest loaded node " << s.summits_per_node() << " summits";
  return out.str();
}

std::string scale_separation_warning(const ScaleSeparation &s) {
  if (s.holds()) return {};
  std::ostringstream out;
  out.precision(4);
  out << "WARNING: no scale separation: the contact is " << 1e3 * s.contact_width << " mm wide, "
      << s.cells_across() << " homogenisation cells of " << 1e3 * s.cell.cell_size << " mm (at least "
      << kMinCellsAcross << " needed); the law's cell average is applied to a contact narrower than that, so its "
      << "friction and wear there are not a cell-converged prediction";
  return out.str();
}

}  // namespace runin::coupling
