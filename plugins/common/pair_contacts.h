// The pass of pair runin/asperity over its neighbour pairs, shared by the LAMMPS host
// (plugins/lammps/pair_runin_asperity.*) and the LIGGGHTS host (plugins/liggghts/pair_runin_asperity_liggghts.*):
// which pairs touch, the contact geometry, runin::tribo::ContactModel::evaluate, the validity checks, forces and
// torques, wear and flattening increments, film removal and the contact sums; also single() and the past-centre
// message. Nothing here touches a host class: the hosts hand in plain atom arrays, their neighbour list with its
// touch flags and histories, the layout of their wear-state fix (WearFix: the column constants) and a thin
// adaptor (Host) for the increments and the energy/virial tally; they keep the dispatch, the reverse
// communication and the messages' delivery.
#ifndef RUNIN_PAIR_CONTACTS_H
#define RUNIN_PAIR_CONTACTS_H

#include "pair_increments.h"
#include "runin_contact_range.h"
#include "runin_contact_sums.h"
#include "tribo/asperity_geometry.h"
#include "tribo/contact_model.h"

#include "lmptype.h"    // NEIGHMASK of the host

#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

namespace runin_pair {

namespace tribo = runin::tribo;

// One touching pair of a step and its history record.
struct TouchingPair {
  int i, j;
  double *history;
};
inline constexpr int kPrefetchAhead = 8;    // contacts between a history's prefetch and its use

// The host's per-atom arrays (owned and ghost atoms).
template <class Tag> struct Atoms {
  double **x, **v, **omega, **f, **torque;
  const double *radius, *rmass;
  const int *type, *mask;
  const Tag *tag;
  int nlocal;
};

// The host's neighbour list, with one touch flag and one history record per neighbour.
struct Neighbours {
  int inum;
  const int *ilist, *numneigh;
  int **firstneigh;
  int **firsttouch;
  double **firsthistory;
};

// The adaptor a pair host hands the pass: increments into `increments`, energy and virial through the pair's
// ev_tally_xyz (a protected member of LAMMPS's Pair: the pair declares this a friend). FILM: the host keeps the
// film coverage of friction models with a film.
// positions: the atoms' own positions where the pass sees other points (the spheres' centres of caps), so that the
// virial is that of the atoms; null: the pass's.
template <class Pair, bool FILM> struct PairHost {
  static constexpr bool has_film = FILM;
  Pair &pair;
  Increments &increments;
  int nlocal, newton_pair;
  double **positions = nullptr;
  void add_wear(int i, double lost, double gained) { increments.add_wear(i, lost, gained, nlocal); }
  void add_flattening(int i, double depth) { increments.add_flattening(i, depth, nlocal); }
  void tally(int i, int j, double energy, const double *fpair, const double *del)
  {
    double own[3];
    if (positions) {
      for (int k = 0; k < 3; k++) own[k] = positions[i][k] - positions[j][k];
      del = own;
    }
    pair.ev_tally_xyz(i, j, nlocal, newton_pair, energy, 0.0, fpair[0], fpair[1], fpair[2], del[0], del[1], del[2]);
  }
};

// What the pass reads besides the atoms. `state`: the wear state's block (WearFix::NCOLUMNS per atom) when the
// worn geometry enters the contact, else null; `reach_rows`: the drop the summit reach sees, at the same stride
// (state + WEAR_DEPTH, or the drop less the body's rise); `increments`: the host takes flattening increments.
struct Step {
  const std::optional<tribo::ContactModel> *models;    // (ntypes + 1)^2, [I][J] seen from type I
  int ntypes1;
  double dt;
  long long timestep;
  bool advance, newton_pair, increments;
  int body_groupbit;
  const double *state = nullptr, *reach_rows = nullptr;
  // surface film (friction models with a film): coverage per summit, removal exposure, 1 / s_r per type
  const double *coverage = nullptr;
  double *film_removal = nullptr;
  const double *film_inverse_removal = nullptr;
};

// A step's settings. `worn_rows`: the wear state's rows when the worn geometry enters the contact (one contiguous
// block, indexed without the row pointers), else null; the reach then sees the wear depth. A host with a rise or a
// film sets reach_rows or the film arrays after.
template <class WearFix>
Step step_of(const std::optional<tribo::ContactModel> *models, int ntypes1, double dt, long long timestep,
             bool advance, bool newton_pair, bool increments, int body_groupbit, double **worn_rows, int nmax)
{
  Step s{models, ntypes1, dt, timestep, advance, newton_pair, increments, body_groupbit};
  s.state = worn_rows && nmax > 0 ? worn_rows[0] : nullptr;
  s.reach_rows = s.state ? s.state + WearFix::WEAR_DEPTH : nullptr;
  return s;
}

// What the pass leaves for the host: the sums, the finite check and the contacts to report.
struct Outcome {
  LAMMPS_NS::RuninContactSums sums;
  double force_sum;        // NaN or inf here: a force or wear volume was not finite
  int invalid_contact;     // first contact outside every contact law's validity (past_centre_message), or -1
  double invalid_force;    // its normal force
  int worst_contact;       // the contact furthest beyond its normal law's range (a counted WARNING), or -1
  double worst_range, beyond_range;    // its range ratio; contacts beyond (ratio > 1)
  std::string invalid;     // the ERROR of the invalid contact (the host stops the run), empty if none
};

template <class W, class = void> struct HasRise : std::false_type {};
template <class W> struct HasRise<W, std::void_t<decltype(W::RISE)>> : std::true_type {};

// Centre distance at which two summits touch: worn summits sit lower by their drop (higher if material was
// deposited). Both passes and single() use it, so they agree bit for bit on which pairs touch.
inline double summit_reach(double radi, double radj, double drop_i, double drop_j)
{
  return radi + radj - (drop_i + drop_j);
}

// How far plastic flattening (not wear) lowered the summits of i and j together: a reload restores it.
template <class WearFix> double flattened_drop(const double *state, const double *radius, int i, int j)
{
  constexpr int NCOL = WearFix::NCOLUMNS, DEPTH = WearFix::WEAR_DEPTH, FLATTENED = WearFix::VOLUME_FLATTENED;
  return tribo::flattened_part_of_drop(radius[i], state[NCOL * i + DEPTH], state[NCOL * i + FLATTENED]) +
         tribo::flattened_part_of_drop(radius[j], state[NCOL * j + DEPTH], state[NCOL * j + FLATTENED]);
}

template <class Tag>
tribo::ContactGeometry pair_geometry(const Atoms<Tag> &a, int i, int j, double overlap, double rinv,
                                     const double *del, double flat)
{
  return tribo::sphere_sphere_geometry(overlap, rinv, del, flat, a.radius[i], a.radius[j], a.rmass[i], a.rmass[j],
                                       a.v[i], a.v[j], a.omega[i], a.omega[j]);
}

template <class WearFix, class Tag>
std::string finish(const Outcome &out, const Atoms<Tag> &a, const Step &s, const std::vector<TouchingPair> &touching,
                   runin_host::ContactRangeMonitor &range);

// One force evaluation over the host's neighbour list. NORMAL, FRICTION: the sub-models (registry indices);
// WEAR: Archard wear into the increments; RESHAPE: worn geometry enters the contact; SUMS: fill the contact
// sums; EVFLAG: tally energy and virial. Host: add_wear(i, lost, gained), add_flattening(i, depth),
// tally(i, j, energy, fpair, del) and `has_film` (whether it keeps the film coverage) (PairHost). The worst contact
// beyond its normal law's range goes to `range` (advancing steps).
template <int NORMAL, int FRICTION, int WEAR, int RESHAPE, int SUMS, int EVFLAG, class WearFix, class Host, class Tag>
[[gnu::always_inline]] inline Outcome contacts(Host &host, const Atoms<Tag> &a, const Neighbours &list, const Step &s,
                                               int eflag, std::vector<TouchingPair> &touching,
                                               runin_host::ContactRangeMonitor &range)
{
  const bool advance = s.advance;
  const double *state = s.state;
  constexpr int NCOL = WearFix::NCOLUMNS;
  constexpr int DEPTH = WearFix::WEAR_DEPTH, FLAT = WearFix::FLAT_RADIUS;
  double **x = a.x, **f = a.f;
  double **torque = a.torque;
  const double *radius = a.radius;
  const int *type = a.type, *mask = a.mask;
  const int body_bit = s.body_groupbit;
  const Tag *tag = a.tag;
  const int nlocal = a.nlocal;
  const bool newton_pair = s.newton_pair;
  const int ntypes1 = s.ntypes1;
  const double step_dt = s.dt;
  const double inv_dt = step_dt > 0.0 ? 1.0 / step_dt : 0.0;
  const std::optional<tribo::ContactModel> *const model_table = s.models;
  constexpr int HISTORY = tribo::contact_history_size<NORMAL>;
  // plastic flattening lowers the summits: only with the worn geometry in the contact, and when advancing
  constexpr bool PLASTIC_MODEL = tribo::FlattensSummits<std::tuple_element_t<NORMAL, tribo::NormalModels>>::value;
  const bool PLASTIC = PLASTIC_MODEL && RESHAPE && advance && s.increments;
  // a friction model with a surface film reads the summits' coverage and adds to their removal exposure
  constexpr bool FILM = tribo::HasFilm<std::tuple_element_t<FRICTION, tribo::FrictionModels>>::value && Host::has_film;
  const double *coverage = s.coverage;
  double *film_removal = s.film_removal;
  const double *film_inverse_removal = s.film_inverse_removal;
  LAMMPS_NS::RuninContactSums local_sums;
  // NaN and inf propagate through the sum of all pair forces: one add per contact replaces a pass over
  // every atom's force
  double force_sum = 0.0;
  int invalid_contact = -1;
  double invalid_force = 0.0;
  int worst_contact = -1;
  double worst_range = 1.0, beyond_range = 0.0;

  const int inum = list.inum;
  const int *ilist = list.ilist, *numneigh = list.numneigh;
  int **firstneigh = list.firstneigh;
  int **firsttouch = list.firsttouch;
  double **firsthistory = list.firsthistory;

  auto wear_depth = [state](int k) { return RESHAPE ? state[NCOL * k + DEPTH] : 0.0; };
  // what the reach sees: rows of the wear state's stride (the drop, or the drop less the body's rise), so the
  // loop reads one value either way
  const double *reach_rows = s.reach_rows;
  auto reach_depth = [reach_rows](int k) { return RESHAPE ? reach_rows[NCOL * k] : 0.0; };

  // Pass 1: the touching pairs of the neighbor list, compacted without a branch per pair (whether a
  // neighbor touches is close to random); pairs that separated lose their history.
  int ntouching = 0;
  for (int ii = 0; ii < inum; ii++) {
    const int i = ilist[ii];
    const int jnum = numneigh[i];
    if (jnum == 0) continue;
    if (ntouching + jnum + kPrefetchAhead > static_cast<int>(touching.size()))
      touching.resize(2 * (ntouching + jnum + kPrefetchAhead));
    TouchingPair *pairs = touching.data();
    const double xi[3] = {x[i][0], x[i][1], x[i][2]};
    const double radi = radius[i];
    const double depth_i = reach_depth(i);
    int *touch = firsttouch[i];
    double *allhistory = firsthistory[i];
    const int *jlist = firstneigh[i];
    for (int jj = 0; jj < jnum; jj++) {
      const int j = jlist[jj] & NEIGHMASK;
      const double del[3] = {xi[0] - x[j][0], xi[1] - x[j][1], xi[2] - x[j][2]};
      const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
      const double reach = summit_reach(radi, radius[j], depth_i, reach_depth(j));
      const bool in_contact = (!RESHAPE || reach > 0.0) && rsq < reach * reach;
      pairs[ntouching] = {i, j, &allhistory[HISTORY * jj]};
      ntouching += in_contact;
      // a pair that was not touching has a zero history already (the hosts' history fixes zero new pairs)
      if (touch[jj] && !in_contact)
        for (int k = 0; k < HISTORY; k++) allhistory[HISTORY * jj + k] = 0.0;
      touch[jj] = in_contact;
    }
  }

  // Pass 2: the contact forces. The histories of all neighbours far exceed the caches and pass 1 did not
  // read them: fetch each a few contacts ahead (the records past ntouching exist, as pass 1 sized the list
  // for it; a prefetch of a stale address is harmless).
  constexpr int HISTORY_LINES = (HISTORY * static_cast<int>(sizeof(double)) + 63) / 64;
  for (int c = 0; c < ntouching; c++) {
    const double *ahead = touching[c + kPrefetchAhead].history;
    for (int line = 0; line < HISTORY_LINES; line++) __builtin_prefetch(ahead + 8 * line, 1);
    const int i = touching[c].i, j = touching[c].j;
    double *history = touching[c].history;
    const int itype = type[i];
    const double radi = radius[i], radj = radius[j];
    const double del[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
    const double rsq = del[0] * del[0] + del[1] * del[1] + del[2] * del[2];
    const double reach = summit_reach(radi, radj, reach_depth(i), reach_depth(j));
    const int jtype = type[j];
    const tribo::ContactModel &model = *model_table[itype * ntypes1 + jtype];
    const double r = std::sqrt(rsq);
    const double rinv = 1.0 / r;
    const double flat =
        RESHAPE ? tribo::combined_flat_radius(state[NCOL * i + FLAT], state[NCOL * j + FLAT]) : 0.0;
    tribo::ContactGeometry g = pair_geometry(a, i, j, reach - r, rinv, del, flat);
    if (RESHAPE) g.summit_drop = std::max(wear_depth(i), 0.0) + std::max(wear_depth(j), 0.0);
    if constexpr (FILM) g.film_coverage = 0.5 * (coverage[i] + coverage[j]);
    // a new contact of flattened summits is a reload: the model restores the state that flattened them
    if (PLASTIC_MODEL && RESHAPE && g.summit_drop > 0.0 && !tribo::has_plastic_history(history))
      g.flattened_drop = flattened_drop<WearFix>(state, radius, i, j);
    const double smaller_radius = std::min(radi, radj);
    const tribo::ContactResult contact = model.evaluate<NORMAL, FRICTION, WEAR>(g, history, step_dt, advance);
    const double fn = contact.normal_force;
    const double *ft = contact.tangential.force;
    const double *normal = g.normal;
    // validity: not past the centre of the smaller summit, and not closing or pushed apart by more than its
    // radius in one step; the first violation is remembered without a branch and reported after the loop
    const bool invalid =
        (std::max(g.overlap + g.summit_drop, std::fabs(g.normal_velocity) * step_dt) > smaller_radius) |
        (fn * step_dt * step_dt > smaller_radius * g.effective_mass);
    const bool first_invalid = invalid & (invalid_contact < 0);
    invalid_contact = first_invalid ? c : invalid_contact;
    invalid_force = first_invalid ? fn : invalid_force;
    const double range = contact.normal.range_ratio;
    beyond_range += range > 1.0;
    worst_contact = range > worst_range ? c : worst_contact;
    worst_range = std::max(range, worst_range);

    const double fpair[3] = {fn * normal[0] + ft[0], fn * normal[1] + ft[1], fn * normal[2] + ft[2]};
    force_sum += fpair[0] + fpair[1] + fpair[2];
    double tor[3];
    tribo::geometry_detail::cross3(normal, ft, tor);
    const bool j_here = newton_pair || j < nlocal;
    // torque about each centre at the contact point, R - delta/2 from it (LAMMPS's pair granular)
    const double arm_i = radi - 0.5 * g.overlap, arm_j = radj - 0.5 * g.overlap;
    for (int k = 0; k < 3; k++) {
      f[i][k] += fpair[k];
      torque[i][k] -= arm_i * tor[k];
    }
    if (j_here)
      for (int k = 0; k < 3; k++) {
        f[j][k] -= fpair[k];
        torque[j][k] -= arm_j * tor[k];
      }

    // with newton off a contact with a ghost is computed on both ranks: count half on each
    const double weight = SUMS && !j_here ? 0.5 : 1.0;
    if (SUMS) {
      const bool j_is_counter = jtype > itype || (jtype == itype && tag[j] > tag[i]);
      const double orient = j_is_counter ? -weight : weight;
      local_sums.normal_force += weight * fn;
      for (int k = 0; k < 3; k++) local_sums.tangential_force[k] += orient * ft[k];
      local_sums.contacts += weight;
      if (!contact.tangential.slipping) local_sums.sticking_contacts += weight;
      local_sums.contact_area += weight * contact.normal.real_area;
      local_sums.adhesion_force += weight * contact.strength.adhesion;
      local_sums.ploughing_force += weight * contact.strength.ploughing;
      local_sums.frictional_power +=
          weight * contact.tangential.force_magnitude * contact.tangential.slip_increment * inv_dt;
      // the reaction on the measured body: contacts that cross its boundary (+ on i, - on j)
      const int side = ((mask[i] & body_bit) != 0) - ((mask[j] & body_bit) != 0);
      for (int k = 0; k < 3; k++) local_sums.body_force[k] += side * weight * fpair[k];
    }

    if constexpr (FILM) {
      // each summit's film is worn over its own body's removal distance (1/s_r of its type, 0: no removal)
      if (advance) {
        const double slip = contact.tangential.slip_increment;
        film_removal[i] += slip * film_inverse_removal[itype];
        if (j_here) film_removal[j] += slip * film_inverse_removal[jtype];
      }
    }
    if (PLASTIC && contact.normal.residual_increment > 0.0) {
      // the summits sink by the growth of the residual interference, shared by the bodies' hardness
      const double share_i = model.flattening_share_i();
      host.add_flattening(i, share_i * contact.normal.residual_increment);
      if (j_here) host.add_flattening(j, (1.0 - share_i) * contact.normal.residual_increment);
    }
    if (WEAR && contact.tangential.slip_increment > 0.0) {
      const tribo::WearExchange &exchange = contact.wear;
      host.add_wear(i, exchange.lost_a, exchange.gained_a);
      if (j_here) host.add_wear(j, exchange.lost_b, exchange.gained_b);
      force_sum += exchange.lost_a + exchange.lost_b;    // an overflowing wear law stops the run too
      if (SUMS) local_sums.wear_volume += weight * contact.worn_volume;
    }

    if (EVFLAG) {
      const double energy = eflag ? model.elastic_energy<NORMAL>(g, history) : 0.0;
      host.tally(i, j, energy, fpair, del);
    }
  }

  Outcome out{SUMS ? local_sums : LAMMPS_NS::RuninContactSums(), force_sum, invalid_contact, invalid_force,
              worst_contact, worst_range, beyond_range, {}};
  out.invalid = finish<WearFix>(out, a, s, touching, range);
  return out;
}

// The ERROR of a contact outside every sphere contact law (Outcome::invalid_contact): two summits pressed past the
// centre of the smaller one, or closing (or pushed apart) by more than its radius in one step.
template <class WearFix, class Tag>
std::string past_centre_message(const Atoms<Tag> &a, const Step &s, const TouchingPair &pair, double normal_force,
                                long long step)
{
  constexpr int NCOL = WearFix::NCOLUMNS, DEPTH = WearFix::WEAR_DEPTH;
  const int i = pair.i, j = pair.j;
  double **x = a.x;
  const double del[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
  const double r = std::sqrt(del[0] * del[0] + del[1] * del[1] + del[2] * del[2]);
  const bool worn = s.state != nullptr;
  const double reach = summit_reach(a.radius[i], a.radius[j], worn ? s.reach_rows[NCOL * i] : 0.0,
                                    worn ? s.reach_rows[NCOL * j] : 0.0);
  const tribo::ContactGeometry g = pair_geometry(a, i, j, reach - r, 1.0 / r, del, 0.0);
  const double drop =
      worn ? std::max(s.state[NCOL * i + DEPTH], 0.0) + std::max(s.state[NCOL * j + DEPTH], 0.0) : 0.0;
  const double interference = g.overlap + drop, approach_per_step = std::fabs(g.normal_velocity) * s.dt;
  const double push_per_step = normal_force * s.dt * s.dt / g.effective_mass;
  const double radius = std::min(a.radius[i], a.radius[j]);
  std::string what;
  if (interference > radius)
    what = fmt::format("interfere by {:.4g} m (overlap of the intact spheres), more than the smaller radius {:.4g} "
                       "m: the summit is pressed past its centre, where no contact law holds", interference, radius);
  else if (approach_per_step > radius)
    what = fmt::format("close at {:.4g} m per step, more than the smaller radius {:.4g} m: the contact is not "
                       "resolved in time", approach_per_step, radius);
  else
    what = fmt::format("are pushed apart by their contact force at {:.4g} m per step squared (F dt^2 / m*), more "
                       "than the smaller radius {:.4g} m: the contact is not resolved in time", push_per_step, radius);
  return fmt::format("pair runin/asperity: at step {} atoms {} and {} {} (load, speed or timestep too large)", step,
                     a.tag[i], a.tag[j], what);
}

// After the pass of an advancing step: its worst contact beyond the normal law's range into `range`. Returns the
// past-centre ERROR of its first invalid contact, else empty.
template <class WearFix, class Tag>
std::string finish(const Outcome &out, const Atoms<Tag> &a, const Step &s, const std::vector<TouchingPair> &touching,
                   runin_host::ContactRangeMonitor &range)
{
  if (out.worst_contact >= 0 && s.advance) {
    const TouchingPair &worst = touching[out.worst_contact];
    range.note(s.timestep, out.beyond_range, out.worst_range, a.tag[worst.i], a.tag[worst.j]);
  }
  if (out.invalid_contact < 0) return {};
  return past_centre_message<WearFix>(a, s, touching[out.invalid_contact], out.invalid_force, s.timestep);
}

// single(): the contact of i and j at rsq as the pass computes it, without changing its history.
// fforce * del is the normal force on i; tangential: the tangential force on i.
struct SingleContact {
  double fforce = 0.0, energy = 0.0, tangential[3] = {0.0, 0.0, 0.0}, contact_radius = 0.0, overlap = 0.0;
  // as Pair::single() returns it: fforce, svector (tangential force on i, contact radius, overlap), the energy
  double returned(double &pair_fforce, double *svector) const
  {
    pair_fforce = fforce;
    for (int k = 0; k < 3; k++) svector[k] = tangential[k];
    svector[3] = contact_radius;
    svector[4] = overlap;
    return energy;
  }
};

// The history record of the pair (i, j) in i's neighbour list, copied into `history` (zeros if j is not there).
inline bool copy_history(const Neighbours &list, int i, int j, int size, double *history)
{
  const int jnum = list.numneigh[i];
  const int *jlist = list.firstneigh[i];
  for (int jj = 0; jj < jnum; jj++)
    if ((jlist[jj] & NEIGHMASK) == j) {
      std::copy_n(&list.firsthistory[i][size * jj], size, history);
      return true;
    }
  return false;
}

// `state`: the wear state's block when the worn geometry enters the contact, else null; `history_of(double *)`
// fills the contact's history record, called only for touching summits. Throws what the kernels throw.
template <class WearFix, class Tag, class HistoryOf>
SingleContact single_contact(const Atoms<Tag> &a, const double *state, const tribo::ContactModel &model,
                             const tribo::ContactModelChoice &choice, bool plastic, int i, int j, double rsq,
                             HistoryOf &&history_of)
{
  constexpr int NCOL = WearFix::NCOLUMNS, DEPTH = WearFix::WEAR_DEPTH, FLAT = WearFix::FLAT_RADIUS;
  SingleContact out;
  const double *row_i = state ? &state[NCOL * i] : nullptr, *row_j = state ? &state[NCOL * j] : nullptr;
  const double depth_i = state ? row_i[DEPTH] : 0.0, depth_j = state ? row_j[DEPTH] : 0.0;
  const double flat = state ? tribo::combined_flat_radius(row_i[FLAT], row_j[FLAT]) : 0.0;
  double rise_i = 0.0, rise_j = 0.0;
  if constexpr (HasRise<WearFix>::value) {
    rise_i = state ? row_i[WearFix::RISE] : 0.0;
    rise_j = state ? row_j[WearFix::RISE] : 0.0;
  }
  const double reach = summit_reach(a.radius[i], a.radius[j], depth_i - rise_i, depth_j - rise_j);
  if (!(reach > 0.0) || rsq >= reach * reach) return out;

  double history[tribo::CONTACT_HISTORY_SIZE] = {0.0};
  history_of(history);
  double **x = a.x;
  const double del[3] = {x[i][0] - x[j][0], x[i][1] - x[j][1], x[i][2] - x[j][2]};
  const double r = std::sqrt(rsq);
  tribo::ContactGeometry g = pair_geometry(a, i, j, reach - r, 1.0 / r, del, flat);
  if (state) g.summit_drop = std::max(depth_i, 0.0) + std::max(depth_j, 0.0);
  if (state && plastic && g.summit_drop > 0.0 && !tribo::has_plastic_history(history))
    g.flattened_drop = flattened_drop<WearFix>(state, a.radius, i, j);
  tribo::ContactResult contact;
  tribo::with_sub_models(choice, [&](auto normal, auto) {
    contact = model.stored_force<decltype(normal)::value>(g, history);
    out.energy = model.elastic_energy<decltype(normal)::value>(g, history);
  });
  out.fforce = contact.normal_force / r;
  for (int k = 0; k < 3; k++) out.tangential[k] = contact.tangential.force[k];
  out.contact_radius = contact.normal.contact_radius;
  out.overlap = g.overlap;
  return out;
}

// The largest radius per type over all ranks (out: ntypes + 1 values): it bounds the contact cutoff.
inline void largest_radius_per_type(const double *radius, const int *type, int nlocal, int ntypes, MPI_Comm world,
                                    double *out)
{
  std::vector<double> local(ntypes + 1, 0.0);
  for (int i = 0; i < nlocal; i++) local[type[i]] = std::max(local[type[i]], radius[i]);
  MPI_Allreduce(local.data(), out, ntypes + 1, MPI_DOUBLE, MPI_MAX, world);
}

}    // namespace runin_pair

#endif
