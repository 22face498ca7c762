// compute runin/roughness on both hosts: the keywords both take (bearing, side, mean), the global vector of the
// summit statistics (runin_roughness_core.h) and the wear-state lookup. `Compute` is the host's Compute class; the
// deriving class is the thin host adaptor (CRTP): its constructor calls the host's Compute constructor through
// this one, reads the arguments with parse_keyword (and its own keywords), then calls start_vector. Messages and
// number tests go through the host's runin_host_api.h. It supplies
//   static constexpr const char *atom_style                 named when the radius is missing
//   double summit(i)                                        the height of owned atom i's summit
//   void more_entries(double *out)                          its entries after the bearing ratios (collective)
#pragma once

#include "runin_host_api.h"
#include "runin_roughness_core.h"

#include "atom.h"
#include "compute.h"
#include "modify.h"
#include "update.h"

#include <fmt/format.h>

#include <string>
#include <utility>
#include <vector>

namespace runin_roughness {

template <class Host, class Compute, class WearState> class RoughnessCompute : public Compute {
 public:
  ~RoughnessCompute() override { delete[] this->vector; }

  void init() override
  {
    if (!this->atom->radius_flag)
      fail(std::string("compute runin/roughness: requires atom attribute radius (") + Host::atom_style + ")");
    // the wear state is created by pair runin/asperity or fix runin/wall, possibly after this compute
    fix_wear = WearState::find(this->modify);
  }

  void compute_vector() override
  {
    this->invoked_vector = this->update->ntimestep;
    const int *mask = this->atom->mask;
    const int groupbit = this->groupbit;
    runin_host::kernel_call(this->lmp, FLERR, "compute runin/roughness", true, [&] {
      runin_roughness::compute_vector(
          this->world, this->atom->nlocal, [&](int i) { return (mask[i] & groupbit) != 0; },
          [&](int i) { return host().summit(i); }, depths, this->vector);
      host().more_entries(this->vector + NFIXED + depths.size());
    });
  }

 protected:
  template <class... Args> explicit RoughnessCompute(Args &&...args) : Compute(std::forward<Args>(args)...) {}

  // One of the keywords both hosts take at arg[iarg]: the index after it, or 0 when it is none of them.
  int parse_keyword(int narg, char **arg, int iarg)
  {
    const std::string keyword = arg[iarg];
    if (keyword == "bearing") {
      if (seen_bearing) fail("compute runin/roughness: keyword 'bearing' given twice");
      seen_bearing = true;
      ++iarg;
      while (iarg < narg && runin_host::is_double(arg[iarg])) {
        const double depth =
            runin_host::finite_number(this->lmp, FLERR, "compute runin/roughness", "bearing depth", arg[iarg]);
        if (!(depth >= 0.0))
          fail(fmt::format("compute runin/roughness: bearing depth must be >= 0, got {}", arg[iarg]));
        depths.push_back(depth);
        ++iarg;
      }
      if (depths.empty())
        fail(fmt::format("compute runin/roughness: keyword 'bearing' needs at least one depth, got {}",
                         iarg < narg ? std::string("'") + arg[iarg] + "'" : std::string("none")));
      return iarg;
    }
    if (keyword == "side") {
      if (iarg + 1 >= narg) fail("compute runin/roughness: keyword 'side' needs a value");
      const std::string value = arg[iarg + 1];
      if (value == "up")
        sign = 1.0;
      else if (value == "down")
        sign = -1.0;
      else
        fail(fmt::format("compute runin/roughness: side must be 'up' or 'down', got '{}'", value));
      return iarg + 2;
    }
    if (keyword == "mean") {
      if (iarg + 1 >= narg) fail("compute runin/roughness: keyword 'mean' needs a value");
      const std::string value = arg[iarg + 1];
      if (value != "z")
        fail(fmt::format("compute runin/roughness: mean must be 'z' (a tilted least-squares plane is not "
                         "implemented), got '{}'", value));
      return iarg + 2;
    }
    return 0;
  }
  // The global vector: the summit statistics, one bearing ratio per depth, then `more` entries of the host.
  void start_vector(int more)
  {
    this->vector_flag = 1;
    this->size_vector = NFIXED + static_cast<int>(depths.size()) + more;
    this->extvector = 0;
    this->vector = new double[this->size_vector];
    for (int k = 0; k < this->size_vector; k++) this->vector[k] = 0.0;
  }
  double wear_column(int i, int column) const { return fix_wear ? fix_wear->state()[i][column] : 0.0; }

  std::vector<double> depths;    // bearing depths below the highest summit
  double sign = 1.0;             // +1: side up (z + r - h); -1: side down (-(z - r + h))
  WearState *fix_wear = nullptr;    // nullptr: no wear state, h = 0

 private:
  bool seen_bearing = false;
  Host &host() { return static_cast<Host &>(*this); }
  [[noreturn]] void fail(const std::string &message) { runin_host::all(this->lmp, FLERR, message); }
};

}    // namespace runin_roughness
