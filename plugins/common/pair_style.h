// The pair class of pair_style runin/asperity that both hosts derive from: the per-type coefficients and contact
// models (allocate, mixing in init_one, wear_scale), the sub-model choice, the pair_style keywords both take, the
// checks and lookups of init_style both do, the compile-time dispatch of the force loop (the host's eval, one per
// sub-model and feature combination, chosen once per step) and the application of the step's wear increments.
// Messages go through the host's runin_host_api.h. The deriving class is the host adaptor (CRTP); it supplies
//   template <int NORMAL, int FRICTION, int WEAR, int RESHAPE, int SUMS, int EVFLAG> void eval(int eflag)
//   void accept_sub_model(kind, name, index)     its own refusals of a chosen sub-model (before it is set)
// and the rest of its Pair API: the neighbour list and contact history, communication, restart, single().
#pragma once

#include "pair_contacts.h"
#include "pair_increments.h"
#include "runin_contact_sums.h"
#include "runin_host_api.h"
#include "tribo/contact_model.h"

#include "atom.h"
#include "compute.h"
#include "memory.h"
#include "modify.h"
#include "update.h"

#include <fmt/format.h>

#include <array>
#include <cstring>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace runin_pair {

template <class Host, class Pair, class WearState>
class PairStyle : public Pair, public LAMMPS_NS::RuninContactSource {
 public:
  double init_one(int i, int j) override
  {
    namespace tribo = runin::tribo;
    if (!this->setflag[i][j]) {
      // an unset I,J pair is mixed from I,I and J,J (Pair::init has checked those are set), sub-model by
      // sub-model: exact for E* and G*, the geometric mean of LAMMPS GRANULAR for interface values, each
      // body keeping its own wear coefficient and hardness
      runin_host::kernel_call(this->lmp, FLERR, fmt::format("pair runin/asperity: mixing types {} {}", i, j), true,
                              [&] {
                                coeff_of(i, j) = tribo::mix_coefficients(choice, coeff_of(i, i), coeff_of(j, j));
                                coeff_of(j, i) = tribo::swap_bodies(choice, coeff_of(i, j));
                              });
    }
    const int n = this->atom->ntypes + 1;
    // wear acceleration (pair_style wear_scale): Archard k of both bodies times the factor, in the models only
    // (the stored coefficients, and so restart files and mixing, keep the material's k)
    const auto scaled = [this](tribo::ContactCoefficients c) {
      auto &wear = c.of(tribo::SubModelKind::wear);
      wear[0] *= wear_scale;    // k_I (coefficients k_I H_I k_J H_J of the archard model)
      wear[2] *= wear_scale;    // k_J
      return c;
    };
    runin_host::kernel_call(this->lmp, FLERR, fmt::format("pair runin/asperity: types {} {}", i, j), true, [&] {
      models[i * n + j].emplace(choice, scaled(coeff_of(i, j)), contact_settings);
      models[j * n + i].emplace(choice, scaled(coeff_of(j, i)), contact_settings);
    });
    return host().list_cutoff(i, j);
  }
  void reset_dt() override { dt = this->update->dt; }
  double memory_usage() override
  {
    return increments.memory_usage() + static_cast<double>(touching.capacity()) * sizeof(TouchingPair);
  }

  // Sums over this rank's contacts in the last force evaluation (read by compute runin/friction).
  const LAMMPS_NS::RuninContactSums &contact_sums() const override { return sums; }
  void measure_body(int groupbit) override { body_groupbit = groupbit; }
  WearState *wear_state() const { return fix_wear; }

 protected:
  explicit PairStyle(LAMMPS_NS::LAMMPS *lmp) : Pair(lmp)
  {
    this->single_enable = 1;
    // single(): normal force (fforce * del), then the tangential force on i, the contact radius and overlap
    this->single_extra = 5;
    this->svector = new double[this->single_extra];
    this->no_virial_fdotr_compute = 1;
  }
  // The host's destructor calls this (LAMMPS's returns before it for a copy).
  void release()
  {
    if (this->allocated) {
      this->memory->destroy(this->setflag);
      this->memory->destroy(this->cutsq);
      delete[] maxrad;
    }
    delete[] this->svector;
  }

  void allocate()
  {
    this->allocated = 1;
    const int n = this->atom->ntypes;
    this->memory->create(this->setflag, n + 1, n + 1, "pair:setflag");
    for (int i = 1; i <= n; i++)
      for (int j = i; j <= n; j++) this->setflag[i][j] = 0;
    this->memory->create(this->cutsq, n + 1, n + 1, "pair:cutsq");
    maxrad = new double[n + 1];
    coeffs.assign((n + 1) * (n + 1), runin::tribo::ContactCoefficients());
  }
  runin::tribo::ContactCoefficients &coeff_of(int itype, int jtype)
  {
    return coeffs[itype * (this->atom->ntypes + 1) + jtype];
  }

  // The list's reach for types i, j: two whole spheres touch within the sum of their radii (a host may list less)
  double list_cutoff(int i, int j) const { return maxrad[i] + maxrad[j]; }

  void set_sub_model(runin::tribo::SubModelKind kind, const std::string &name)
  {
    const int index = runin_host::kernel_call(this->lmp, FLERR, "pair_style runin/asperity", true,
                                              [&] { return runin::tribo::find_sub_model(kind, name); });
    host().accept_sub_model(kind, name, index);
    choice.index[static_cast<int>(kind)] = index;
  }
  bool plastic_normal() const    // the normal sub-model is elastic/plastic (summits flatten)
  {
    using runin::tribo::SubModelKind;
    return runin::tribo::registered_sub_models(SubModelKind::normal)[choice.of(SubModelKind::normal)]
        .flattens_summits;
  }
  // The per-atom wear state exists from pair_style on, so dumps and computes can name it before a run.
  void attach_wear_state()
  {
    if (!fix_wear) fix_wear = WearState::find_or_create(this->modify);
  }

  // One of the pair_style keywords both hosts take (wear, archard, reshape, normal, friction, transfer, restick):
  // whether `keyword` is one of them.
  bool setting(const std::string &keyword, const std::string &value)
  {
    namespace tribo = runin::tribo;
    const auto number = [&](const char *name) {
      return runin_host::finite_number(this->lmp, FLERR, "pair_style runin/asperity", name, value.c_str());
    };
    if (keyword == "wear") {
      wear_on = runin_host::yes_no(this->lmp, FLERR, value, "pair_style runin/asperity: wear");
    } else if (keyword == "archard") {
      if (value == "plain")
        contact_settings.archard_form = tribo::ArchardForm::plain;
      else if (value == "thesis")
        contact_settings.archard_form = tribo::ArchardForm::thesis;
      else
        fail(fmt::format("pair_style runin/asperity: archard must be 'plain' or 'thesis', got '{}'", value));
    } else if (keyword == "reshape") {
      reshape = runin_host::yes_no(this->lmp, FLERR, value, "pair_style runin/asperity: reshape");
    } else if (keyword == "normal") {
      set_sub_model(tribo::SubModelKind::normal, value);
    } else if (keyword == "friction") {
      set_sub_model(tribo::SubModelKind::friction, value);
    } else if (keyword == "transfer") {
      const double fraction = number("transfer fraction");
      if (!(fraction >= 0.0 && fraction <= 1.0))
        fail(fmt::format("pair_style runin/asperity: transfer fraction must be in [0, 1], got '{}'", value));
      contact_settings.transfer_fraction = fraction;
    } else if (keyword == "restick") {
      const double speed = number("restick speed");
      if (!(speed >= 0.0))
        fail(fmt::format("pair_style runin/asperity: restick speed must be >= 0 m/s, got '{}'", value));
      contact_settings.restick_speed = speed;
    } else {
      return false;
    }
    return true;
  }

  // init_style: the history size of the chosen normal model, which may not change once the history fix exists.
  void size_history(bool history_exists)
  {
    const int wanted_history = runin::tribo::contact_history_size_of(choice.of(runin::tribo::SubModelKind::normal));
    if (history_exists && wanted_history != history_size)
      fail(fmt::format("pair runin/asperity: the normal model changed after the first run ({} history values per "
                       "contact, {} now); define the pair style anew (pair_style none first)",
                       history_size, wanted_history));
    history_size = wanted_history;
  }
  // init_style: contact sums cost a few operations per contact: only when a compute can read them.
  void request_sums()
  {
    sums_requested = false;
    for (int i = 0; i < this->modify->ncompute; i++)
      if (strcmp(this->modify->compute[i]->style, "runin/friction") == 0) sums_requested = true;
    sums = LAMMPS_NS::RuninContactSums();
  }

  // The force loop of this step: the host's eval specialised for the sub-models and features in use.
  void evaluate(int eflag, bool advance, bool worn_geometry)
  {
    namespace tribo = runin::tribo;
    constexpr int NMODELS = std::tuple_size_v<tribo::NormalModels> * std::tuple_size_v<tribo::FrictionModels>;
    static const auto table = eval_table(std::make_integer_sequence<int, (NMODELS << NFLAGS)>());
    const int models_index = choice.of(tribo::SubModelKind::normal) * std::tuple_size_v<tribo::FrictionModels> +
                             choice.of(tribo::SubModelKind::friction);
    // Archard wear only with wear yes: the increments of a plastic model without wear carry flattening alone
    const int index = (models_index << NFLAGS) | (wear_on && advance ? 8 : 0) | (worn_geometry ? 4 : 0) |
                      (sums_requested ? 2 : 0) | (this->evflag ? 1 : 0);
    runin_host::kernel_call(this->lmp, FLERR, "pair runin/asperity", false, [&] { (host().*table[index])(eflag); });
  }
  // The listed owned atoms' increments (complete: after any reverse communication) into the state, the geometry
  // refreshed; a summit worn or flattened past its equator has left the truncated-sphere geometry.
  void apply_increments()
  {
    const int used_up = increments.apply(*fix_wear, this->atom->radius);
    if (used_up >= 0)
      runin_host::one(this->lmp, FLERR,
                      used_up_message(this->update->ntimestep, this->atom->tag[used_up],
                                      fix_wear->state()[used_up][WearState::WEAR_DEPTH], this->atom->radius[used_up]));
  }

  int history_size = runin::tribo::TANGENTIAL_HISTORY_SIZE;    // per contact: tangential + normal model's (init)
  double dt = 0.0;
  bool wear_on = true;
  bool reshape = true;                                // worn geometry (summit drop, flat) enters the normal force
  runin::tribo::ContactSettings contact_settings;    // Archard form, transfer, re-stick
  double wear_scale = 1.0;    // pair_style wear_scale: factor on Archard k of both bodies (wear acceleration);
                              // applied to the models built in init_one, not to the stored coefficients
  runin::tribo::ContactModelChoice choice;           // the sub-models, one per kind (pair_style keywords)
  std::vector<runin::tribo::ContactCoefficients> coeffs;    // (ntypes+1)^2; [J][I] is seen from type J
  std::vector<std::optional<runin::tribo::ContactModel>> models;    // same layout, built in init_one
  LAMMPS_NS::RuninContactSums sums;
  bool sums_requested = false;    // a compute runin/friction exists (set at init): fill 'sums'
  int body_groupbit = 0;          // group whose contact reaction the sums carry (0: none)
  double *maxrad = nullptr;       // per type

  // wear, transfer and plastic-flattening increments of one step
  Increments increments;
  std::vector<TouchingPair> touching;    // the touching pairs of one step (grows, never shrinks)
  WearState *fix_wear = nullptr;

 private:
  // the shared pass's adaptor tallies energy and virial through Pair's protected ev_tally_xyz
  template <class, bool> friend struct PairHost;
  Host &host() { return static_cast<Host &>(*this); }
  [[noreturn]] void fail(const std::string &message) { runin_host::all(this->lmp, FLERR, message); }

  using EvalFunction = void (Host::*)(int);
  static constexpr int NFLAGS = 4;    // WEAR, RESHAPE, SUMS, EVFLAG
  // Index = ((normal * NFRICTION + friction) << NFLAGS) | flags
  template <int... Index>
  static std::array<EvalFunction, sizeof...(Index)> eval_table(std::integer_sequence<int, Index...>)
  {
    constexpr int NFRICTION = std::tuple_size_v<runin::tribo::FrictionModels>;
    return {{&Host::template eval<(Index >> NFLAGS) / NFRICTION, (Index >> NFLAGS) % NFRICTION, (Index >> 3) & 1,
                                  (Index >> 2) & 1, (Index >> 1) & 1, Index & 1>...}};
  }
};

}    // namespace runin_pair
