#include "runin_liggghts_style_maps.h"

namespace runin_liggghts {
namespace detail {
template struct Expose<FixMapTag, &LAMMPS_NS::Modify::fix_map>;
template struct Expose<ComputeMapTag, &LAMMPS_NS::Modify::compute_map>;
}    // namespace detail

FixMap &fix_map(LAMMPS_NS::Modify *modify)
{
  return *(modify->*member(detail::FixMapTag{}));
}

ComputeMap &compute_map(LAMMPS_NS::Modify *modify)
{
  return *(modify->*member(detail::ComputeMapTag{}));
}
}    // namespace runin_liggghts
