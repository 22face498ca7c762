#include "runin_liggghts_comm_access.h"

namespace runin_liggghts {
namespace {
template <class Tag, typename Tag::type Member> struct Expose {
  friend typename Tag::type member(Tag) { return Member; }
};
#define RUNIN_EXPOSE(NAME, TYPE)                                   \
  struct NAME##Tag {                                               \
    using type = TYPE LAMMPS_NS::Comm::*;                          \
    friend type member(NAME##Tag);                                 \
  };                                                               \
  template struct Expose<NAME##Tag, &LAMMPS_NS::Comm::NAME>;
RUNIN_EXPOSE(nswap, int)
RUNIN_EXPOSE(sendnum, int *)
RUNIN_EXPOSE(recvnum, int *)
RUNIN_EXPOSE(sendproc, int *)
RUNIN_EXPOSE(recvproc, int *)
RUNIN_EXPOSE(firstrecv, int *)
RUNIN_EXPOSE(sendlist, int **)
#undef RUNIN_EXPOSE
}    // namespace

SwapPlan swap_plan(LAMMPS_NS::Comm *comm)
{
  return {comm->*member(nswapTag{}),    comm->*member(sendnumTag{}),   comm->*member(recvnumTag{}),
          comm->*member(sendprocTag{}), comm->*member(recvprocTag{}), comm->*member(firstrecvTag{}),
          comm->*member(sendlistTag{})};
}

}    // namespace runin_liggghts
