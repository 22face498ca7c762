// Scale separation between a homogenised state law and the continuum contact that reads it. The law is an average
// over one cell (a square of side L_cell holding N summits); a continuum node may take it as its own only if the
// contact is many cells wide and each node holds many summits. Criterion used here: the contact at least
// kMinCellsAcross cells wide (a cell no wider than a third of the contact), and the statistical weight of the
// smallest loaded node stated as its summit count (eta A_node, eta = N / L_cell^2).
#pragma once

#include <optional>
#include <string>

#include "coupling/state_law.h"

namespace runin::coupling {

inline constexpr double kMinCellsAcross = 3.0;

struct CellScale {
  double cell_size = 0.0;        // m, side of the homogenisation cell
  double summit_density = 0.0;   // 1/m^2, summits of the rough body per nominal area
};

// From the law's `surface` metadata (nside x spacing, summits): nullopt when the law carries none (a synthetic law).
std::optional<CellScale> cell_scale(const StateLaw &law);

struct ScaleSeparation {
  CellScale cell;
  double contact_width = 0.0;          // m, narrowest extent of the loaded contact
  double smallest_node_area = 0.0;     // m^2, of the loaded continuum nodes
  double cells_across() const { return contact_width / cell.cell_size; }
  double summits_per_node() const { return cell.summit_density * smallest_node_area; }
  bool holds() const { return cells_across() >= kMinCellsAcross * (1.0 - 1e-12); }  // exactly 3 cells holds
};

// One summary line: "contact 0.34 mm = 0.35 cells of 0.96 mm; smallest node 3660 summits; ...".
std::string describe(const ScaleSeparation &s);
// The WARNING when it does not hold (empty when it does).
std::string scale_separation_warning(const ScaleSeparation &s);

}  // namespace runin::coupling
