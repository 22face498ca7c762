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
#include "runin_contact_sums.h"
#include "runin_timestep_guard.h"
#include "tribo/contact.h"
#include "tribo/friction_strength.h"
#include "tribo/wear.h"

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace LAMMPS_NS {

class PairRuninAsperity : public Pair, public RuninContactSource, public runin_lammps::FiniteForcePair {
 public:
  // Per type-pair coefficients (SI units), validated where they are parsed.
  struct Coefficients {
    double effective_modulus = 0.0;        // E* [Pa]
    double effective_shear_modulus = 0.0;  // G* [Pa]
    double restitution = 1.0;              // e [-]
    double mu_static = 0.0, mu_kinetic = 0.0, slip_weakening_distance = 0.0;
    double wear_coefficient = 0.0;         // k [-]
    double hardness_i = 0.0, hardness_j = 0.0;  // H of the type-I and type-J asperity [Pa]
    // optional (trailing pair_coeff keywords), used with 'friction strength'
    double shear_strength = 0.0;           // tau_s [Pa]
    double ploughing_factor = 1.0;         // scales Rabinowicz's mu_p [-]

    // From {E*, G*, e, mu_s, mu_k, d_c, k, H_I, H_J}, the order of the explicit pair_coeff form.
    static constexpr int NPACKED = 9;
    static Coefficients unpack(const double *values);
  };

  // Kernel objects for one type pair, rebuilt (validated) from the coefficients at every init; all the
  // force loop reads for a contact, in one place.
  struct TypePairModel {
    double effective_modulus;          // E* [Pa]
    double effective_shear_modulus;    // G* [Pa]
    runin::tribo::RestitutionDamping damping;
    runin::tribo::StaticKineticFriction friction;
    runin::tribo::ArchardWear wear;
    runin::tribo::AdhesionPloughing strength;
    runin::tribo::WearExchangeRule exchange;    // type-I atom's share of the wear volume, transfer fraction
  };

  PairRuninAsperity(class LAMMPS *);
  ~PairRuninAsperity() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double init_one(int, int) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
  void reset_dt() override;
  void transfer_history(double *, double *) override;
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double memory_usage() override;
  double atom2cut(int) override;
  double radii2cut(double, double) override;

  // Sums over this rank's contacts in the last force evaluation (read by compute runin/friction).
  const RuninContactSums &contact_sums() const override { return sums; }
  class FixRuninWearState *wear_state() const { return fix_wear; }
  bool wear_enabled() const { return wear_on; }

 protected:
  enum HistoryIndex { SPRING_X = 0, SPRING_Y, SPRING_Z, SLIP, HISTORY_SIZE };
  enum class FrictionModel { coulomb, strength };

  double dt;
  bool wear_on;
  bool reshape;                    // worn geometry (summit drop, flat) enters the normal force
  runin::tribo::ArchardForm archard_form;
  FrictionModel friction_model;
  double transfer_fraction;        // part of the removed volume deposited on the counter-asperity
  double restick_speed;            // below this tangential speed a contact heals to mu_s (0: never)
  std::vector<Coefficients> coeffs;    // (ntypes+1)^2; [J][I] has the hardnesses swapped
  std::vector<std::optional<TypePairModel>> models;    // same layout, built in init_one
  RuninContactSums sums;
  bool sums_requested;             // a compute runin/friction exists (set at init): fill 'sums'

  // Wear and transfer increments of one step, owned + ghost, reverse-communicated: {lost, gained} per atom
  // side by side (one cache line per contact side). All zero between steps: an atom is listed when its
  // first nonzero increment arrives (sums of volumes >= 0 stay nonzero), and only the listed entries are
  // applied (owned atoms) and cleared, instead of passes over all owned and ghost atoms.
  double *increment;               // 2 per atom
  int nmax_increment;
  int *worn_owned, *worn_ghost;    // the listed atoms, owned and ghost (nmax_increment + 1 each)
  int nworn_owned, nworn_ghost;
  void add_wear(int i, double lost, double gained, int nlocal)
  {
    // branch-free: the slot is always written and kept only for an atom listed now
    double *slot = &increment[2 * i];
    const bool was_zero = slot[0] == 0.0 && slot[1] == 0.0;
    slot[0] += lost;
    slot[1] += gained;
    const bool first = was_zero && (slot[0] != 0.0 || slot[1] != 0.0), owned = i < nlocal;
    worn_owned[nworn_owned] = i;
    worn_ghost[nworn_ghost] = i;
    nworn_owned += first && owned;
    nworn_ghost += first && !owned;
  }
  struct TouchingPair {
    int i, j;
    double *history;
  };
  std::vector<TouchingPair> touching;    // the touching pairs of one step (grows, never shrinks)
  double *maxrad;            // per type

  class FixDummy *fix_dummy;
  class FixNeighHistory *fix_history;
  class FixRuninWearState *fix_wear;

  void allocate();
  void attach_wear_state();
  void grow_increments();
  // The force loop, specialised at compile time on the features in use (OPT-package style).
  template <int WEAR, int RESHAPE, int STRENGTH, int SUMS, int EVFLAG> void eval(int eflag);
  using EvalFunction = void (PairRuninAsperity::*)(int);
  template <int... Index>
  static std::array<EvalFunction, sizeof...(Index)> eval_table(std::integer_sequence<int, Index...>);
  Coefficients &coeff_of(int itype, int jtype);
  Coefficients read_coefficients_file(const std::string &file, const std::string &material_i,
                                      const std::string &material_j);
  void validate(const Coefficients &c, const char *origin);
  void read_optional_coefficients(Coefficients &c, int narg, char **arg, int first);
};

}    // namespace LAMMPS_NS

#endif
#endif
