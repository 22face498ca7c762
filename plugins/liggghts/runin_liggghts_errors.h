// Bad input and kernel failures as one LIGGGHTS ERROR line (LIGGGHTS's Error takes a C string only and
// ends the process itself: MPI_Finalize + exit(1) for error->all, MPI_Abort for error->one).
#pragma once

#include "error.h"
#include "lammps.h"
#include "update.h"

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <utility>

namespace runin_liggghts {

[[noreturn]] inline void all(LAMMPS_NS::LAMMPS *lmp, const char *file, int line, const std::string &message)
{
  lmp->error->all(file, line, message.c_str());
  std::abort();    // not reached: Error::all exits
}

[[noreturn]] inline void one(LAMMPS_NS::LAMMPS *lmp, const char *file, int line, const std::string &message)
{
  lmp->error->one(file, line, message.c_str());
  std::abort();    // not reached: Error::one aborts
}

// Runs `body`; an exception from the RunIn kernels becomes one ERROR "<where>: <what>". `collective`: every
// rank runs `body` on the same input (error->all); otherwise error->one.
template <class Body>
decltype(auto) kernel_call(LAMMPS_NS::LAMMPS *lmp, const char *file, int line, const std::string &where,
                           bool collective, Body &&body)
{
  try {
    return std::forward<Body>(body)();
  } catch (const std::exception &e) {
    const std::string message = where + ": " + e.what();
    if (collective) all(lmp, file, line, message);
    one(lmp, file, line, message);
  }
}

// Whether `text` is a number as LAMMPS's utils::is_double accepts it (digits, sign, '.', exponent).
inline bool is_double(const char *text)
{
  if (!text || !*text) return false;
  char *end = nullptr;
  std::strtod(text, &end);
  if (*end != '\0') return false;
  for (const char *c = text; *c; ++c)
    if (!(std::isdigit(static_cast<unsigned char>(*c)) || *c == '-' || *c == '+' || *c == '.' || *c == 'e' ||
          *c == 'E'))
      return false;
  return true;
}

// A named argument that must be a finite number: one ERROR naming it otherwise.
inline double finite_number(LAMMPS_NS::LAMMPS *lmp, const char *file, int line, const std::string &where,
                            const std::string &name, const char *text)
{
  if (is_double(text)) {
    const double value = std::strtod(text, nullptr);
    if (std::isfinite(value)) return value;
  }
  all(lmp, file, line, where + ": " + name + " must be a finite number, got '" + (text ? text : "") + "'");
}

inline bool yes_no(LAMMPS_NS::LAMMPS *lmp, const char *file, int line, const std::string &value,
                   const std::string &what)
{
  if (value == "yes" || value == "on" || value == "true" || value == "1") return true;
  if (value == "no" || value == "off" || value == "false" || value == "0") return false;
  all(lmp, file, line, fmt::format("{} must be 'yes' or 'no', got '{}'", what, value));
}

// The RunIn styles take SI coefficients: another unit system is one ERROR naming the deck's units.
inline void require_si_units(LAMMPS_NS::LAMMPS *lmp, const char *file, int line, const std::string &style)
{
  const char *units = lmp->update->unit_style;
  if (units && std::strcmp(units, "si") == 0) return;
  all(lmp, file, line,
      style + ": the coefficients are in SI; this deck uses 'units " + (units ? units : "?") + "'; use 'units si'");
}

}    // namespace runin_liggghts
