// The few LAMMPS API differences between the versions RunIn builds against, in one place. The RUNIN_* feature
// macros come from CMake's probes of the headers in use (plugins/lammps/CMakeLists.txt), not from dates.
#pragma once

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "fix.h"
#include "modify.h"
#include "utils.h"
#include "neighbor.h"
#include "pair.h"

#include <cstring>
#include <string>

#ifndef RUNIN_NEIGHBOR_ADD_REQUEST
#include "neigh_request.h"
#endif

namespace runin_compat {

// A neighbour list sized by particle radius, with per-contact history.
inline void request_size_history_list(LAMMPS_NS::Pair *pair, LAMMPS_NS::Neighbor *neighbor, int instance)
{
#ifdef RUNIN_NEIGHBOR_ADD_REQUEST
  (void) instance;
  neighbor->add_request(pair, LAMMPS_NS::NeighConst::REQ_SIZE | LAMMPS_NS::NeighConst::REQ_HISTORY);
#else
  const int request = neighbor->request(pair, instance);
  neighbor->requests[request]->size = 1;
  neighbor->requests[request]->history = 1;
#endif
}

// A half list with contact history whose reach is the pair's type cutoff (init_one), not the atoms' sizes.
inline void request_history_list(LAMMPS_NS::Pair *pair, LAMMPS_NS::Neighbor *neighbor, int instance)
{
#ifdef RUNIN_NEIGHBOR_ADD_REQUEST
  (void) instance;
  neighbor->add_request(pair, LAMMPS_NS::NeighConst::REQ_HISTORY);
#else
  const int request = neighbor->request(pair, instance);
  neighbor->requests[request]->history = 1;
#endif
}

inline void reverse_comm(LAMMPS_NS::Comm *comm, LAMMPS_NS::Pair *pair)
{
#ifdef RUNIN_COMM_OVERLOADS
  comm->reverse_comm(pair);
#else
  comm->reverse_comm_pair(pair);
#endif
}

inline void reverse_comm(LAMMPS_NS::Comm *comm, LAMMPS_NS::Fix *fix)
{
#ifdef RUNIN_COMM_OVERLOADS
  comm->reverse_comm(fix);
#else
  comm->reverse_comm_fix(fix);
#endif
}

inline void forward_comm(LAMMPS_NS::Comm *comm, LAMMPS_NS::Fix *fix)
{
#ifdef RUNIN_COMM_OVERLOADS
  comm->forward_comm(fix);
#else
  comm->forward_comm_fix(fix);
#endif
}

// utils::logical (LAMMPS 2022 on): yes/no/on/off/true/false/1/0; anything else is an ERROR naming it.
// A word outside the set gives an ERROR naming `what` (utils::logical's own message names no argument).
inline bool logical(LAMMPS_NS::LAMMPS *lmp, const std::string &value, const char *what)
{
  const bool yes = value == "yes" || value == "on" || value == "true" || value == "1";
  if (!yes && !(value == "no" || value == "off" || value == "false" || value == "0"))
    lmp->error->all(FLERR, fmt::format("{} must be 'yes' or 'no', got '{}'", what, value));
#ifdef RUNIN_UTILS_LOGICAL
  return LAMMPS_NS::utils::logical(FLERR, value, false, lmp) == 1;
#else
  return yes;
#endif
}

// Per-atom radius, mass, spin and torque: what atom_style sphere provides (Atom::sphere_flag is gone in
// LAMMPS 2023+; these flags exist in every release).
inline bool sphere_atoms(const LAMMPS_NS::Atom *atom)
{
  return atom->radius_flag && atom->rmass_flag && atom->omega_flag && atom->torque_flag;
}

// The fix with this ID, or nullptr: Modify::get_fix_by_id (LAMMPS 2022+) where the headers have it, since
// Modify::find_fix is deprecated there.
inline LAMMPS_NS::Fix *fix_by_id(LAMMPS_NS::Modify *modify, const std::string &id)
{
#ifdef RUNIN_MODIFY_GET_FIX_BY_ID
  return modify->get_fix_by_id(id);
#else
  const int index = modify->find_fix(id);
  return index >= 0 ? modify->fix[index] : nullptr;
#endif
}

// Whether a fix of this style exists.
inline bool fix_by_style(LAMMPS_NS::Modify *modify, const char *style)
{
  for (int k = 0; k < modify->nfix; k++)
    if (std::strcmp(modify->fix[k]->style, style) == 0) return true;
  return false;
}

}    // namespace runin_compat
