// LIGGGHTS 3.8 keeps Modify's fix and compute style maps private (LAMMPS has them public, and lmp_runin
// inserts its styles there). An explicit template instantiation may name a private member (C++ [temp.explicit]),
// which gives a pointer to each map without changing LIGGGHTS.
#pragma once

#include "modify.h"

#include <map>
#include <string>

namespace runin_liggghts {

using FixCreator = LAMMPS_NS::Fix *(*)(LAMMPS_NS::LAMMPS *, int, char **);
using ComputeCreator = LAMMPS_NS::Compute *(*)(LAMMPS_NS::LAMMPS *, int, int, char **);
using FixMap = std::map<std::string, FixCreator>;
using ComputeMap = std::map<std::string, ComputeCreator>;

namespace detail {
struct FixMapTag {
  using type = FixMap *LAMMPS_NS::Modify::*;
  friend type member(FixMapTag);
};
struct ComputeMapTag {
  using type = ComputeMap *LAMMPS_NS::Modify::*;
  friend type member(ComputeMapTag);
};
template <class Tag, typename Tag::type Member> struct Expose {
  friend typename Tag::type member(Tag) { return Member; }
};
}    // namespace detail

FixMap &fix_map(LAMMPS_NS::Modify *modify);
ComputeMap &compute_map(LAMMPS_NS::Modify *modify);

}    // namespace runin_liggghts
