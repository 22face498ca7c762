// Read access to LIGGGHTS 3.8's forward-communication plan (Comm keeps its swaps protected), for the
// non-blocking exchange of the worn geometry (FixRuninWearStateLiggghts): the same explicit-instantiation
// device as runin_liggghts_style_maps.h, without changing LIGGGHTS.
#pragma once

#include "comm.h"

namespace runin_liggghts {

struct SwapPlan {
  int nswap;
  const int *sendnum, *recvnum, *sendproc, *recvproc, *firstrecv;
  int *const *sendlist;
};

SwapPlan swap_plan(LAMMPS_NS::Comm *comm);

}    // namespace runin_liggghts
