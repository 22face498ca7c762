// Turning bad input and kernel failures into LAMMPS ERRORs, for every RunIn style.
#ifndef LMP_RUNIN_ERRORS_H
#define LMP_RUNIN_ERRORS_H

#include "citeme.h"
#include "error.h"
#include "exceptions.h"
#include "lammps.h"
#include "update.h"
#include "utils.h"

#include <cmath>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <optional>
#include <string>
#include <utility>

namespace runin_lammps {

// One ERROR on every rank (the caller's FLERR).
[[noreturn]] inline void all(LAMMPS_NS::LAMMPS *lmp, const char *file, int line, const std::string &message)
{
  lmp->error->all(file, line, message);
}

// One ERROR on this rank only (a rank's own atoms or contacts).
[[noreturn]] inline void one(LAMMPS_NS::LAMMPS *lmp, const char *file, int line, const std::string &message)
{
  lmp->error->one(file, line, message);
}

// Runs `body` and returns its result; an exception from the RunIn kernels (a bad coefficient, a failed
// calibration) becomes one ERROR "<where>: <what>" instead of std::terminate. `collective`: every rank runs
// `body` on the same input (parsing, init), so error->all; otherwise (a rank's own contacts) error->one.
// `file`, `line`: the caller's FLERR, so the ERROR points at the call site.
template <class Body>
decltype(auto) kernel_call(LAMMPS_NS::LAMMPS *lmp, const char *file, int line, const std::string &where,
                           bool collective, Body &&body)
{
  try {
    return std::forward<Body>(body)();
  } catch (const LAMMPS_NS::LAMMPSException &) {
    throw;    // an ERROR already reported by the body (LAMMPS built with exceptions): pass it on, once
  } catch (const std::exception &e) {
    const std::string message = where + ": " + e.what();
    if (collective) lmp->error->all(file, line, message);
    lmp->error->one(file, line, message);
  }
}

// `text` as a finite number, or nothing ("1e999" reads as inf, "nan", a word). strtod, not
// utils::numeric or ValueTokenizer::next_double: newer LAMMPS stops on an overflow itself, with a
// message naming no argument, so every host would word the same mistake differently.
inline std::optional<double> parse_finite(const char *text)
{
  if (!text || !LAMMPS_NS::utils::is_double(text)) return std::nullopt;
  const double value = std::strtod(text, nullptr);
  if (!std::isfinite(value)) return std::nullopt;
  return value;
}

// A named argument that must be a finite number: one ERROR
// "<where>: <name> must be a finite number, got '<text>'" at the caller's FLERR.
inline double finite_number(LAMMPS_NS::LAMMPS *lmp, const char *file, int line, const std::string &where,
                            const std::string &name, const char *text)
{
  if (const auto value = parse_finite(text)) return *value;
  lmp->error->all(file, line, where + ": " + name + " must be a finite number, got '" + (text ? text : "") + "'");
}

// The RunIn styles take SI coefficients (potentials/*.runin, the explicit forms) and print SI units; in another
// unit system every force would be off by orders of magnitude without a word. One ERROR naming the deck's units.
inline void require_si_units(LAMMPS_NS::LAMMPS *lmp, const char *file, int line, const std::string &style)
{
  const char *units = lmp->update->unit_style;
  if (units && std::strcmp(units, "si") == 0) return;
  lmp->error->all(file, line,
                  style + ": the coefficients are in SI; this deck uses 'units " + (units ? units : "?") + "'; use 'units si'");
}

// Adds the papers of the models in use to LAMMPS's citation list (log.cite); none with -nocite.
template <class Entries> void cite(LAMMPS_NS::LAMMPS *lmp, const Entries &entries)
{
  if (!lmp->citeme) return;
  for (const char *entry : entries) lmp->citeme->add(entry);
}

}    // namespace runin_lammps

#endif
