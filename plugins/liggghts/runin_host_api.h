// The LIGGGHTS side of the host adaptor that the styles shared by both hosts (plugins/common) call: one ERROR on
// every rank or on one, a kernel exception as one ERROR, the number and yes/no tests of the style arguments.
#pragma once

#include "runin_liggghts_errors.h"

namespace runin_host {
using runin_liggghts::all;
using runin_liggghts::finite_number;
using runin_liggghts::is_double;
using runin_liggghts::kernel_call;
using runin_liggghts::one;
using runin_liggghts::yes_no;
}    // namespace runin_host
