// `runin homogenise`: one cell sample's output (the columns of the in.rve_wall contract) on the state law's grid of
// worn depths h (doc/homogenise.md, "From samples to the law"). No I/O beyond the table: unit-tested on its own.
#pragma once

#include <array>
#include <stdexcept>
#include <vector>

#include "coupling/ave_time_reader.h"
#include "coupling/homogenise.h"
#include "coupling/state_law.h"

namespace runin::coupling {

// The contract columns of one sample (cell units: s and the rates at the accelerated k).
struct CellSeries {
  std::vector<double> s, h, h_cf, mu_body, rq, rsk, area_fraction;
  std::vector<double> contact_fraction;  // contacts / rough summits; empty when not known
};

// Reads v_s, v_h, v_h_cf, v_mu_body, v_rq, v_rsk, v_area_fraction; throws std::runtime_error for a missing column
// (coupling::InputFormatError) or a non-finite value (naming the column and row). With rough_summits > 0 and a
// v_contacts column (in.rve_rough), also the contact fraction v_contacts / rough_summits.
CellSeries cell_series(const coupling::AveTimeTable &table, double rough_summits = 0.0);

// 0 .. depth in `points` even steps (the last one exactly depth); with first > 0: 0, then points - 1 depths in
// geometric progression from first to depth, for a law whose state changes fast in the first nanometres and slowly
// over hundreds (cycle jumping with a tolerance relative to h, doc/rve_cell.md "Mild wear").
std::vector<double> depth_grid(double depth, long points, double first = 0.0);


// Every field of the state law on `grid` for one sample run at `acceleration` (physical s = acceleration x cell s,
// physical rates = cell rates / acceleration). Uses the rows with s > 0; h made non-decreasing by a running
// maximum; Rq, Rsk and the sliding distance linear in h between the last row below a grid depth and the first at
// or above it; mu_body, the area fraction and the contact fraction (a few contacts at a time: noisy), past h = 0, the least-squares line
// over the rows within half the grid step on each side of the depth, at the depth, kept within those rows' range (the bracket
// when fewer than 3 rows; h = 0 is the first sliding row); wear rates a
// least-squares slope dh/ds over the rows within one grid step (at least 3 rows). Throws std::runtime_error when
// fewer than 2 rows slide or the sample's h stops short of grid.back() ("reached h = ... m of depth ... m").
DepthCurves resample_on_depth_grid(const CellSeries &cell, const std::vector<double> &grid, double acceleration);

}  // namespace runin::coupling
