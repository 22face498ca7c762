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
#include "pair_style.h"
#include "runin_timestep_guard.h"

#include <string>
#include <vector>

namespace LAMMPS_NS {

class FixRuninWearState;

// The LAMMPS adaptor of the pair both hosts share (pair_style.h): LAMMPS's contact history (FixNeighHistory),
// newton on or off (reverse communication of the increments), restart files, the surface film, the rise of a
// body's free surface, the citations and the timestep guard.
class PairRuninAsperity : public runin_pair::PairStyle<PairRuninAsperity, Pair, FixRuninWearState>,
                          public runin_lammps::FiniteForcePair {
 public:
  PairRuninAsperity(class LAMMPS *);
  ~PairRuninAsperity() override;
  void compute(int, int) override;
  void settings(int, char **) override;
  void coeff(int, char **) override;
  void init_style() override;
  double single(int, int, int, int, double, double, double, double &) override;
  void write_restart(FILE *) override;
  void read_restart(FILE *) override;
  void write_restart_settings(FILE *) override;
  void read_restart_settings(FILE *) override;
#ifdef RUNIN_TRANSFER_HISTORY_TYPES
  void transfer_history(double *, double *, int, int) override;
#else
  void transfer_history(double *, double *) override;
#endif
  int pack_reverse_comm(int, int, double *) override;
  void unpack_reverse_comm(int, int *, double *) override;
  double atom2cut(int) override;
  double radii2cut(double, double) override;

  bool wear_enabled() const { return wear_on; }

 protected:
  static constexpr int MAX_HISTORY_SIZE = runin::tribo::CONTACT_HISTORY_SIZE;

  bool rise_on = false;            // flattened volume raises the surface of its body (volume-conserving)
  bool rise_free = false;          // ... only the summits out of contact (rise free; Pullen and Williamson)
  std::vector<double> contact_flag;    // rise free: 1 for a summit in contact this step (owned + ghost)
  bool reverse_contacts = false;   // reverse communication carries contact_flag instead of the increments
  std::vector<double> reach_drop;  // with rise_on: per atom (owned + ghost, stride NCOLUMNS) drop less rise
  void raise_free_surfaces();    // this step's flattened volume per type, before the increments are applied
  bool from_restart;               // coefficients came from a restart file (pair_style must not change models)

  // caps (pair_style caps UP DOWN INTERFERENCE): each atom sits at the top of its summit, which faces +z (type
  // caps_up) or -z (caps_down); the sphere's centre is one radius behind it. The neighbour list then needs the
  // reach of two caps (sqrt(2 (R_i + R_j) interference)), not a summit's diameter, and every step checks that no
  // summit stands further into the other body than `caps_interference` allows (else a contact could be missed).
  int caps_up = 0, caps_down = 0;    // 0: whole spheres (atoms at the centres)
  double caps_interference = 0.0;    // [m]
  double **centres = nullptr;        // caps: the spheres' centres of owned + ghost atoms (the pass's positions)
  int centres_nmax = 0;
  bool caps() const { return caps_up > 0; }
  double caps_cutoff(int i, int j) const;    // the list cutoff of types i, j with caps
  double list_cutoff(int i, int j) const { return caps() ? caps_cutoff(i, j) : PairStyle::list_cutoff(i, j); }
  void place_centres(int first, int last);    // centres of atoms [first, last)
  void check_caps();                          // ERROR if a contact could lie beyond the list's cutoff
  void parse_caps(int narg, char **arg, int iarg);

  // the increments are owned + ghost, reverse-communicated
  bool comm_gained, comm_flattened;    // which increments reverse communication carries besides 'lost'

  class FixDummy *fix_dummy;
  class FixNeighHistory *fix_history;
  // Surface film (friction models with a film, friction junction/film): the per-summit coverage, its initial value
  // (pair_style keyword coverage), and per type (from its own I,I pair) the growth exposure k_g dt and 1 / s_r
  class FixRuninFilm *fix_film = nullptr;
  double initial_coverage = 1.0;
  std::vector<double> film_growth;
  std::vector<double> film_inverse_removal_;
  bool film_friction() const;

  // The force loop, specialised at compile time on the sub-models and features in use (OPT-package style).
  // flatten: the contact model, Mindlin spring and helpers are inlined whatever GCC's size heuristics say
  // (near their limit, a small change to the contact law outlined ContactModel::evaluate or mindlin_spring
  // and cost 5-20 % of the loop's instructions).
  template <int NORMAL, int FRICTION, int WEAR, int RESHAPE, int SUMS, int EVFLAG> [[gnu::flatten]] void eval(int eflag);
  friend class runin_pair::PairStyle<PairRuninAsperity, Pair, FixRuninWearState>;
  void accept_sub_model(runin::tribo::SubModelKind kind, const std::string &name, int index);
  // The shared pass's (pair_contacts.h) view of the atoms and of the neighbour list with the contact history (eval
  // and single())
  runin_pair::Atoms<tagint> loop_atoms() const;
  runin_pair::Neighbours neighbours() const;
};

}    // namespace LAMMPS_NS

#endif
#endif
