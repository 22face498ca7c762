// The LAMMPS side of the host adaptor that the styles shared by both hosts (plugins/common) call: one ERROR on every
// rank or on one, a kernel exception as one ERROR, the number and yes/no tests of the style arguments.
#pragma once

#include "runin_errors.h"
#include "runin_lammps_compat.h"

#include <string>

namespace runin_host {
using runin_lammps::all;
using runin_lammps::finite_number;
using runin_lammps::kernel_call;
using runin_lammps::one;
inline bool is_double(const char *text) { return LAMMPS_NS::utils::is_double(text); }
inline bool yes_no(LAMMPS_NS::LAMMPS *lmp, const char *, int, const std::string &value, const std::string &what)
{
  return runin_compat::logical(lmp, value, what.c_str());
}
}    // namespace runin_host
