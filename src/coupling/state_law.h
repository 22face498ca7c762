// A homogenised run-in state law: tables over nominal pressure p and the surface state h (mean worn
// depth of the rough body: its worn volume over the nominal area), built by `runin homogenise` from
// rough-on-flat cell runs and read by the continuum contact nodes. Format: doc/state_law.md.
//
// Interpolation: linear in h; between pressures a power law, ln(value) linear in ln p, where both neighbours are
// positive (else linear in ln p). Along h the last grid value holds beyond the grid (the cell ran to
// its steady state there); a pressure outside the grid is an error, or, with OutOfRange::Clamp, the nearest
// grid pressure, counted in a RangeUse so the caller can report how often it happened. OutOfRange::Archard
// is Clamp for friction and surface state, but keeps the wear rates and the real-area fraction exact in p:
// they are scaled by p / p_edge from the nearest grid pressure p_edge (Archard: dh/ds = k p / H at any p;
// a plastic real area is proportional to the load).
#pragma once

#include <array>
#include <optional>
#include <utility>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace runin::coupling {

enum class StateField {
  MuBody,               // friction the bodies feel, |F_t| / F_n of the counterface reaction
  Rq,                   // m, RMS of the summit heights of the rough body
  Rsk,                  // -, skewness of the summit heights
  AreaFraction,         // -, real contact area / nominal area
  WearRate,             // m/m, dh/ds of the rough body at the physical wear coefficient (acceleration removed)
  CounterfaceWearRate,  // m/m, mean worn depth rate of the counterface (physical)
  SlidingDistance,      // m, physical sliding distance the cell took to reach h (for comparisons, not dynamics)
  ContactFraction,      // -, contacts / summits of the rough body: the fraction of its sliding a summit spends in
                        //    contact (surface-film kinetics, doc/surface_films.md); optional, laws built before it
                        //    lack it
};
inline constexpr std::size_t state_field_count = 8;
// A field a law may lack (an empty table); the others are required.
constexpr bool optional_field(StateField field) { return field == StateField::ContactFraction; }
const char *to_string(StateField field);  // the JSON key: "mu_body", "rq", ...

enum class Band { Mean, Low, High };  // Low/High: the seed band (see doc/state_law.md)
enum class OutOfRange { Error, Clamp, Archard };
const char *to_string(OutOfRange policy);  // "error", "clamp", "archard"

// How often a lookup left the pressure grid (clamped) or the worn-depth grid (held at the last row).
struct RangeUse {
  long below_pressure = 0;
  long above_pressure = 0;
  long beyond_depth = 0;
  long lookups = 0;
};

struct StateFieldTable {
  // [pressure index][depth index]; Low/High may be empty (no band).
  std::vector<std::vector<double>> mean, low, high;
};

struct StateLawValues {
  double mu_body = 0.0, rq = 0.0, rsk = 0.0, area_fraction = 0.0, wear_rate = 0.0, counterface_wear_rate = 0.0;
  double contact_fraction = 0.0;  // 0 when the law lacks the field
};

class StateLaw {
 public:
  // Throws std::invalid_argument naming the defect: >= 2 pressures (positive, strictly increasing), >= 2 depths
  // (first 0, strictly increasing), every field present with mean of size pressures x depths, finite values,
  // mu_body, rq, area_fraction, wear rates >= 0, low <= mean <= high.
  StateLaw(std::vector<double> pressure, std::vector<double> worn_depth,
           std::array<StateFieldTable, state_field_count> fields, nlohmann::json metadata = nlohmann::json::object());

  // JSON form (doc/state_law.md); from_json throws InputFormatError ("<path>: ...", one line) on any defect.
  static StateLaw from_json(const nlohmann::json &document, const std::string &path);
  static StateLaw read_file(const std::string &path);
  nlohmann::json to_json() const;

  const std::vector<double> &pressure() const { return pressure_; }
  const std::vector<double> &worn_depth() const { return depth_; }
  const StateFieldTable &table(StateField field) const { return fields_[static_cast<std::size_t>(field)]; }
  const nlohmann::json &metadata() const { return metadata_; }  // material, surface, samples, provenance
  bool has_band() const;
  bool has(StateField field) const { return !table(field).mean.empty(); }  // false: an optional field it lacks
  // The fields OutOfRange::Archard scales with p outside the grid: the wear rates, the real-area fraction and the
  // contact fraction (plastic contacts: their number and area go with the load).
  static bool proportional_to_pressure(StateField field);
  // The two bodies' materials the law was homogenised for (metadata material.rough and material.counterface, as
  // `runin homogenise` writes them from its material file); nullopt when the law names none (a synthetic law).
  std::optional<std::pair<std::string, std::string>> materials() const;

  // One field at (p, h). Error policy: std::out_of_range naming p and the grid. `use` (optional) counts. A field
  // the law lacks: std::invalid_argument.
  double value(StateField field, double pressure, double worn_depth, Band band = Band::Mean,
               OutOfRange policy = OutOfRange::Error, RangeUse *use = nullptr) const;
  // All dynamic fields at once (one grid search).
  StateLawValues values(double pressure, double worn_depth, OutOfRange policy = OutOfRange::Error,
                        RangeUse *use = nullptr) const;

  // The pressure half of a lookup, found once for a caller that reads one pressure at many depths (a contact
  // node over a wear step): the bracketing grid pressures, the weight, and which side was clamped. slice()
  // throws like values(); each read below counts in `use` exactly as one values() call would.
  struct PressureSlice {
    std::size_t ip = 0;
    double wp = 0.0;    // weight of the upper grid pressure
    int clamped = 0;    // -1: below the grid, +1: above (OutOfRange::Clamp/Archard), 0: inside
    double proportional_scale = 1.0;   // Archard: p / p_edge for wear rates and area fraction, else 1
  };
  PressureSlice slice(double pressure, OutOfRange policy = OutOfRange::Error) const;
  double value(StateField field, const PressureSlice &slice, double worn_depth, RangeUse *use = nullptr) const;
  // wear_rate and counterface_wear_rate only (what a wear step needs)
  void wear_rates(const PressureSlice &slice, double worn_depth, RangeUse *use, double &wear_rate,
                  double &counterface_wear_rate) const;

 private:
  struct Cell {
    std::size_t ip = 0, ih = 0;
    double wp = 0.0, wh = 0.0;  // weights of the upper neighbours
    double proportional_scale = 1.0;
  };
  Cell locate(double pressure, double worn_depth, OutOfRange policy, RangeUse *use) const;
  Cell locate(const PressureSlice &slice, double worn_depth, RangeUse *use) const;
  double interpolate(const std::vector<std::vector<double>> &grid, const Cell &cell) const;

  std::vector<double> pressure_, log_pressure_, depth_;
  std::array<StateFieldTable, state_field_count> fields_;
  nlohmann::json metadata_;
};

}  // namespace runin::coupling
