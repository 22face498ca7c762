#include "runin_styles.h"

#include "compute_runin_friction.h"
#include "compute_runin_roughness.h"
#include "fix_runin_wall.h"
#include "fix_runin_wear_jump.h"
#include "fix_runin_film.h"
#include "fix_runin_wear_state.h"
#include "pair_runin_asperity.h"
#include "runin_timestep_guard.h"

#include "force.h"
#include "lammps.h"
#include "modify.h"

using namespace LAMMPS_NS;

namespace runin_lammps {

namespace {
template <typename T> void *create_pair(void *lmp)
{
  return new T(static_cast<LAMMPS *>(lmp));
}
template <typename T> void *create_with_args(void *lmp, int narg, char **arg)
{
  return new T(static_cast<LAMMPS *>(lmp), narg, arg);
}
template <typename T> Pair *pair_creator(LAMMPS *lmp)
{
  return new T(lmp);
}
template <typename T> Fix *fix_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new T(lmp, narg, arg);
}
template <typename T> Compute *compute_creator(LAMMPS *lmp, int narg, char **arg)
{
  return new T(lmp, narg, arg);
}
}    // namespace

const std::vector<StyleEntry> &styles()
{
  static const std::vector<StyleEntry> table = {
      {"pair", "runin/asperity", "RunIn asperity contact: Hertz or elastic/plastic normal, Mindlin with coulomb, strength, brizmer, junction or junction/film friction, Archard wear",
       &create_pair<PairRuninAsperity>, nullptr},
      {"fix", "RUNIN/WEAR_STATE", "RunIn per-atom wear state (internal)", nullptr,
       &create_with_args<FixRuninWearState>},
      {"fix", "runin/wear/jump", "RunIn cycle jumping of asperity wear (slow wear: each phase stands for M phases)",
       nullptr, &create_with_args<FixRuninWearJump>},
      {"fix", "RUNIN/FILM", "RunIn per-atom surface-film coverage (internal)", nullptr,
       &create_with_args<FixRuninFilm>},
      {"fix", "RUNIN/FINITE_CHECK", "RunIn non-finite force check (internal)", nullptr,
       &create_with_args<FixRuninFiniteCheck>},
      {"fix", "runin/wall", "RunIn asperities against a rigid flat counterface (displacement or load control)",
       nullptr, &create_with_args<FixRuninWall>},
      {"compute", "runin/friction", "RunIn contact force, friction and wear sums", nullptr,
       &create_with_args<ComputeRuninFriction>},
      {"compute", "runin/roughness", "RunIn surface statistics (Ra, Rq, Rsk, Rku, Rp, Rv, Rz, bearing ratio)",
       nullptr, &create_with_args<ComputeRuninRoughness>},
  };
  return table;
}

void register_styles(LAMMPS *lmp)
{
  (*lmp->force->pair_map)["runin/asperity"] = &pair_creator<PairRuninAsperity>;
  (*lmp->modify->fix_map)["RUNIN/WEAR_STATE"] = &fix_creator<FixRuninWearState>;
  (*lmp->modify->fix_map)["runin/wear/jump"] = &fix_creator<FixRuninWearJump>;
  (*lmp->modify->fix_map)["RUNIN/FILM"] = &fix_creator<FixRuninFilm>;
  (*lmp->modify->fix_map)["RUNIN/FINITE_CHECK"] = &fix_creator<FixRuninFiniteCheck>;
  (*lmp->modify->fix_map)["runin/wall"] = &fix_creator<FixRuninWall>;
  (*lmp->modify->compute_map)["runin/friction"] = &compute_creator<ComputeRuninFriction>;
  (*lmp->modify->compute_map)["runin/roughness"] = &compute_creator<ComputeRuninRoughness>;
}

}    // namespace runin_lammps
