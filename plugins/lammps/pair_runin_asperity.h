// pair_style runin/asperity: asperity-asperity contact between rough bodies.
// A thin adapter around the runin::tribo kernels: Hertz (or, for worn asperities, Sneddon's
// flat punch + Hertz) normal force with restitution damping, a Mindlin spring with per-contact
// history and a static/kinetic Coulomb limit (optionally from adhesion + ploughing), and Archard
// wear that flattens and lowers the asperities, with optional transfer to the counter-asperity.
#ifdef PAIR_CLASS
// clang-format off
PairStyle(runin/asperity,PairRuninAsperity);
// clang-format on
#else

#ifndef LMP_PAIR_RUNIN_ASPERITY_H
#define LMP_PAIR_RUNIN_ASPERITY_H

#include "pair.h"
#include "pair_contacts.h"
#include "pair_increments.h"
#include "runin_contact_sums.h"
#include "runin_timestep_guard.h"
#include "tribo/contact_model.h"

#include <algorithm>
#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace LAMMPS_NS {

class PairRuninAsperity : public Pair, public RuninContactSource, public runin_lammps::FiniteForcePair {
 public:
  PairRuninAsperity(class LAMMPS *);
  ~PairRuninAsperity() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  double single(int, int, int, int, double, double, double, double &) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  void reset_dt() override;
#ifdef RUNIN_TRANSFER_HISTORY_TYPES
  void transfer_history(double *, double *, int, int) override;
#else
  void transfer_history(double *, double *) override;
#endif
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;
  double atom2cut(int) override;
  double radii2cut(double, double) override;

  // Sums over this rank's contacts in the last force evaluation (read by compute runin/friction).
  const RuninContactSums &contact_sums() const override { return sums; }
  void measure_body(int groupbit) override { body_groupbit = groupbit; }
  class FixRuninWearState *wear_state() const { return fix_wear; }
  bool wear_enabled() const { return wear_on; }

 protected:
  static constexpr int MAX_HISTORY_SIZE = runin::tribo::CONTACT_HISTORY_SIZE;
  int history_size;    // per contact: the tangential slots and the chosen normal model's (set at init)

  double dt;
  bool wear_on;
  bool reshape;                    // worn geometry (summit drop, flat) enters the normal force
  bool rise_on = false;            // flattened volume raises the surface of its body (volume-conserving)
  bool rise_free = false;          // ... only the summits out of contact (rise free; Pullen and Williamson)
  std::vector<double> contact_flag;    // rise free: 1 for a summit in contact this step (owned + ghost)
  bool reverse_contacts = false;   // reverse communication carries contact_flag instead of the increments
  std::vector<double> reach_drop;  // with rise_on: per atom (owned + ghost, stride NCOLUMNS) drop less rise
  void raise_free_surfaces();    // this step's flattened volume per type, before the increments are applied
  runin::tribo::ContactSettings contact_settings;    // Archard form, transfer, re-stick
  double wear_scale = 1.0;    // pair_style wear_scale: factor on Archard k of both bodies (wear acceleration);
                              // applied to the models built in init_one, not to the stored coefficients
  runin::tribo::ContactModelChoice choice;           // the sub-models, one per kind (pair_style keywords)
  bool from_restart;               // coefficients came from a restart file (pair_style must not change models)
  std::vector<runin::tribo::ContactCoefficients> coeffs;    // (ntypes+1)^2; [J][I] is seen from type J
  std::vector<std::optional<runin::tribo::ContactModel>> models;    // same layout, built in init_one
  RuninContactSums sums;
  bool sums_requested;             // a compute runin/friction exists (set at init): fill 'sums'
  int body_groupbit;               // group whose contact reaction the sums carry (0: none)

  // Wear, transfer and plastic-flattening increments of one step, owned + ghost, reverse-communicated
  runin_pair::Increments increments;
  bool comm_gained, comm_flattened;    // which increments reverse communication carries besides 'lost'
  std::vector<runin_pair::TouchingPair> touching;    // the touching pairs of one step (grows, never shrinks)
  double *maxrad;            // per type

  class FixDummy *fix_dummy;
  class FixNeighHistory *fix_history;
  class FixRuninWearState *fix_wear;
  // Surface film (friction models with a film, friction junction/film): the per-summit coverage, its initial value
  // (pair_style keyword coverage), and per type (from its own I,I pair) the growth exposure k_g dt and 1 / s_r
  class FixRuninFilm *fix_film = nullptr;
  double initial_coverage = 1.0;
  std::vector<double> film_growth;
  std::vector<double> film_inverse_removal_;
  bool film_friction() const;

  void allocate();
  void attach_wear_state();
  // The force loop, specialised at compile time on the sub-models and features in use (OPT-package style).
  // flatten: the contact model, Mindlin spring and helpers are inlined whatever GCC's size heuristics say
  // (near their limit, a small change to the contact law outlined ContactModel::evaluate or mindlin_spring
  // and cost 5-20 % of the loop's instructions).
  template <int NORMAL, int FRICTION, int WEAR, int RESHAPE, int SUMS, int EVFLAG> [[gnu::flatten]] void eval(int eflag);
  using EvalFunction = void (PairRuninAsperity::*)(int);
  static constexpr int NFLAGS = 4;    // WEAR, RESHAPE, SUMS, EVFLAG
  template <int... Index>
  static std::array<EvalFunction, sizeof...(Index)> eval_table(std::integer_sequence<int, Index...>);
  // The shared pass (pair_contacts.h): its adaptor, and its view of the atoms and of the neighbour list with the
  // contact history (eval and single())
  friend struct runin_pair::PairHost<PairRuninAsperity, true>;
  runin_pair::Atoms<tagint> loop_atoms() const;
  runin_pair::Neighbours neighbours() const;
  runin::tribo::ContactCoefficients &coeff_of(int itype, int jtype);
  void set_sub_model(runin::tribo::SubModelKind kind, const std::string &name);
  bool plastic_normal() const;    // the normal sub-model is elastic/plastic (summits flatten)
};

}    // namespace LAMMPS_NS

#endif
#endif
