// The coefficient grammar of the asperity contact, one parser for every host (pair_coeff runin/asperity of the
// LAMMPS and the LIGGGHTS pair, the coefficients of fix runin/wall):
//   keyword block  normal NAME v.. damping NAME v.. tangential NAME v.. friction NAME v.. wear NAME v..
//                  (each kind once, in any order, each followed by exactly the coefficients the registry lists)
//   explicit       E* G* e mu_s mu_k d_c k H [options]
//   file           file PATH MATERIAL_I MATERIAL_J [options]
//   options        tau_s X, plough X, S_y X, nu X, f X, alpha X, interface STATE, f_film X, s_r X, k_g X
// The explicit and file forms (and the wall's value groups) name ContactParameters; contact_coefficients() turns
// them into the ContactCoefficients the keyword block gives directly, and checked() runs the checks, Tabor's
// fallback WARNING and the contact model's validation once for all of them. Errors go through a thin host adaptor
// (Host), one ERROR line each; nothing here touches a host class.
#ifndef RUNIN_COEFFICIENT_GRAMMAR_H
#define RUNIN_COEFFICIENT_GRAMMAR_H

#include "tribo/contact_model.h"
#include "tribo/friction_strength.h"
#include "tribo/material_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <cmath>
#include <functional>
#include <iterator>
#include <string>
#include <strings.h>
#include <vector>

namespace runin_coeff {

namespace tribo = runin::tribo;

// What a host hands the parser. `fail`: one ERROR line on every rank, does not return; `warning`: printed once (the
// first rank); `is_number`: the host's notion of a number word; `material`: the named pair of a RunIn coefficient
// file, or fail. `style` starts every message ("pair_coeff runin/asperity", "fix runin/wall"); `film`: the host
// keeps a per-summit film coverage (the film keywords are known).
struct Host {
  std::string style;
  bool film = false;
  std::function<void(const std::string &)> fail;
  std::function<void(const std::string &)> warning;
  std::function<bool(const char *)> is_number;
  std::function<tribo::ContactParameters(const char *path, const char *a, const char *b)> material;
};

[[noreturn]] inline void fail(const Host &host, const std::string &message)
{
  host.fail(message);
  std::abort();    // not reached: the host's fail stops the run
}

// A RunIn kernel call whose exception becomes one ERROR "<where>: <what>" (fail is called outside the try, so an
// ERROR the host raises as an exception is not caught again).
template <class Body> decltype(auto) kernel(const Host &host, const std::string &where, Body &&body)
{
  std::string message;
  try {
    return body();
  } catch (const std::exception &e) {
    message = where + ": " + e.what();
  }
  fail(host, message);
}

// A named argument that must be a finite number: "<where>: <name> must be a finite number, got '<text>'".
inline double number(const Host &host, const std::string &where, const std::string &name, const char *text)
{
  if (text && host.is_number(text)) {
    const double value = std::strtod(text, nullptr);
    if (std::isfinite(value)) return value;
  }
  fail(host, where + ": " + name + " must be a finite number, got '" + (text ? text : "") + "'");
}

// The contact parameters of a coefficient file's material pair (E*, G* from the two materials, their hardnesses and
// yield, the pair entry and its interface lines): what the hosts' material readers return.
inline tribo::ContactParameters parameters_of(const tribo::MaterialPairEntry &entry)
{
  auto p = tribo::contact_parameters(entry.a, entry.b, entry.restitution, entry.mu_static, entry.mu_kinetic,
                                     entry.slip_weakening_distance, entry.wear_coefficient);
  p.interface_factors = entry.interface_factor;
  return p;
}

// ---- the named values: the one place a coefficient's name maps onto ContactParameters ----

// The explicit form's values, in order.
inline constexpr int kExplicitValues = 8;
inline constexpr const char *kExplicitNames[kExplicitValues] = {"E*", "G*", "e", "mu_s", "mu_k", "d_c", "k", "H"};
// The options after the explicit and file forms (a number each; interface takes a state).
inline constexpr const char *kOptions[] = {"tau_s", "plough", "S_y", "nu", "f", "alpha"};
inline constexpr const char *kFilmOptions[] = {"f_film", "s_r", "k_g"};

// Sets the named value; false for a name that is none. H is both bodies' hardness, H_i and H_j one each; S_y
// marks the yield strength as given (no Tabor fallback).
inline bool set_named(tribo::ContactParameters &p, const std::string &name, double value)
{
  if (name == "E*") p.effective_modulus = value;
  else if (name == "G*") p.effective_shear_modulus = value;
  else if (name == "e") p.restitution = value;
  else if (name == "mu_s") p.mu_static = value;
  else if (name == "mu_k") p.mu_kinetic = value;
  else if (name == "d_c") p.slip_weakening_distance = value;
  else if (name == "k") p.wear_coefficient = value;
  else if (name == "H") p.hardness_i = p.hardness_j = value;
  else if (name == "H_i") p.hardness_i = value;
  else if (name == "H_j") p.hardness_j = value;
  else if (name == "tau_s") p.shear_strength = value;
  else if (name == "plough") p.ploughing_factor = value;
  else if (name == "S_y") {
    p.yield_strength = value;
    p.yield_from_hardness = false;
  }
  else if (name == "nu") p.poisson_ratio = value;
  else if (name == "f") p.interface_coefficient = value;
  else if (name == "alpha") p.junction_alpha = value;
  else if (name == "f_film") p.film_interface_coefficient = value;
  else if (name == "s_r") p.film_removal_distance = value;
  else if (name == "k_g") p.film_growth_rate = value;
  else return false;
  return true;
}

// Tabor's fallback where no yield strength was given: S_y = H / 2.8 of the softer body (the file form's materials
// fall back per material in tribo::contact_parameters, through the same tribo::tabor_yield_strength).
inline void yield_from_hardness(tribo::ContactParameters &p)
{
  p.yield_strength = tribo::tabor_yield_strength(std::min(p.hardness_i, p.hardness_j));
  p.yield_from_hardness = true;
}

// "a b c"
template <class It> std::string joined(It begin, It end)
{
  std::string out;
  for (It it = begin; it != end; ++it) out += (it == begin ? "" : " ") + std::string(*it);
  return out;
}

// "a, b, c or d"
template <class Names> std::string listed(const Names &names)
{
  std::string out;
  const int n = static_cast<int>(names.size());
  for (int k = 0; k < n; k++) out += (k == 0 ? "" : k == n - 1 ? " or " : ", ") + std::string(names[k]);
  return out;
}

inline std::vector<std::string> option_names(bool film)
{
  std::vector<std::string> names(std::begin(kOptions), std::end(kOptions));
  names.push_back("interface");
  if (film) names.insert(names.end(), std::begin(kFilmOptions), std::end(kFilmOptions));
  return names;
}

// The options from arg[first] to arg[narg): one named value each, or 'interface STATE'.
inline void read_options(const Host &host, tribo::ContactParameters &p, int narg, char **arg, int first)
{
  const std::vector<std::string> known = option_names(host.film);
  for (int iarg = first; iarg < narg; iarg += 2) {
    const std::string keyword = arg[iarg];
    if (keyword == "interface") {
      // the state's friction factor m comes from the coefficient file (contact_coefficients applies it)
      if (iarg + 1 >= narg)
        fail(host, fmt::format("{}: interface needs a state ({})", host.style, tribo::interface_state_list()));
      p.interface_state = kernel(host, host.style, [&] { return tribo::find_interface_state(arg[iarg + 1]); });
      continue;
    }
    if (std::find(known.begin(), known.end(), keyword) == known.end())
      fail(host, fmt::format("{}: unknown keyword '{}' (expected {})", host.style, keyword, listed(known)));
    set_named(p, keyword, number(host, host.style, keyword, iarg + 1 < narg ? arg[iarg + 1] : ""));
  }
}

// ---- the keyword block ----

// A word meant as a number that the host does not read as one ('nan', 'inf', '4.8e10x', '0x10'): it goes to number(),
// which names it, instead of ending a block's values (which gave "takes 1 coefficient(s), got 0").
inline bool number_like(const char *word)
{
  if (!word || word[0] == '\0') return false;
  return std::strchr("+-.0123456789", word[0]) != nullptr || strncasecmp(word, "nan", 3) == 0 ||
         strncasecmp(word, "inf", 3) == 0;
}

inline int kind_of(const char *word)
{
  for (int k = 0; k < tribo::kSubModelKinds; k++)
    if (std::strcmp(word, tribo::sub_model_kind_name(static_cast<tribo::SubModelKind>(k))) == 0) return k;
  return -1;
}

inline const tribo::SubModelInfo &chosen(const tribo::ContactModelChoice &choice, tribo::SubModelKind kind)
{
  return tribo::registered_sub_models(kind)[choice.of(kind)];
}

// Blocks 'KIND NAME values...' from arg[iarg] on, until narg or, with `complete`, until every kind is given or a
// word that names no kind (the wall's keywords follow the block). `fixed`: each block must name the model `choice` holds (pair_style's);
// otherwise the blocks set `choice`. iarg ends after the last block.
inline tribo::ContactCoefficients read_blocks(const Host &host, int narg, char **arg, int &iarg,
                                              tribo::ContactModelChoice &choice, bool fixed, bool complete)
{
  tribo::ContactCoefficients c;
  std::array<bool, tribo::kSubModelKinds> given{};
  auto all_given = [&] { return std::all_of(given.begin(), given.end(), [](bool g) { return g; }); };
  while (iarg < narg && !(complete && all_given())) {
    const int kind_index = kind_of(arg[iarg]);
    if (kind_index < 0 && complete) break;    // the host's next keyword: the missing blocks are named below
    if (kind_index < 0)
      fail(host, fmt::format("{}: unknown keyword '{}' (expected normal, damping, tangential, friction or wear)",
                             host.style, arg[iarg]));
    if (given[kind_index]) fail(host, fmt::format("{}: the {} block is given twice", host.style, arg[iarg]));
    const auto kind = static_cast<tribo::SubModelKind>(kind_index);
    if (iarg + 1 >= narg) fail(host, fmt::format("{}: {} needs a model name", host.style, arg[iarg]));
    const int model = kernel(host, host.style, [&] { return tribo::find_sub_model(kind, arg[iarg + 1]); });
    if (fixed && model != choice.of(kind))
      fail(host, fmt::format("{}: {} model '{}' differs from pair_style's '{}'", host.style, arg[iarg], arg[iarg + 1],
                             chosen(choice, kind).name));
    choice.index[kind_index] = model;
    const tribo::SubModelInfo &info = tribo::registered_sub_models(kind)[model];
    const int n = info.coefficient_count();
    int got = 0;
    while (iarg + 2 + got < narg && host.is_number(arg[iarg + 2 + got])) got++;
    const std::string where = fmt::format("{}: {} {}", host.style, arg[iarg], info.name);
    if (got < n && iarg + 2 + got < narg && number_like(arg[iarg + 2 + got]))
      number(host, where, info.coefficient_names[got], arg[iarg + 2 + got]);
    if (got != n)
      fail(host, fmt::format("{}: {} model '{}' takes {} coefficient(s) ({}), got {}", host.style, arg[iarg],
                             info.name, n, joined(info.coefficient_names.begin(), info.coefficient_names.end()), got));
    for (int k = 0; k < n; k++)
      c.values[kind_index].push_back(number(host, where, info.coefficient_names[k], arg[iarg + 2 + k]));
    given[kind_index] = true;
    iarg += 2 + n;
  }
  for (int k = 0; k < tribo::kSubModelKinds; k++)
    if (!given[k]) {
      const auto kind = static_cast<tribo::SubModelKind>(k);
      fail(host, fmt::format("{}: the {} block is missing (e.g. '{} {} ...')", host.style, tribo::sub_model_kind_name(kind),
                             tribo::sub_model_kind_name(kind), chosen(choice, kind).name));
    }
  return c;
}

// The position of a coefficient of the chosen model by its registry name (-1 where the model has none): the one
// spelling of each coefficient (tau_s, S_y, k_i, ...) is the registry's.
inline int named_index(const tribo::ContactModelChoice &choice, tribo::SubModelKind kind, const char *name)
{
  const auto &names = chosen(choice, kind).coefficient_names;
  for (std::size_t k = 0; k < names.size(); k++)
    if (std::strcmp(names[k], name) == 0) return static_cast<int>(k);
  return -1;
}

inline const double *named_coefficient(const tribo::ContactModelChoice &choice, const tribo::ContactCoefficients &c,
                                       tribo::SubModelKind kind, const char *name)
{
  const int k = named_index(choice, kind, name);
  return k >= 0 && k < static_cast<int>(c.of(kind).size()) ? &c.of(kind)[k] : nullptr;
}

// ---- one form in, one checked struct out ----

// A contact's coefficients as read: the keyword block's values, or the named parameters of the other forms.
struct Read {
  const char *origin = "explicit";    // keywords, explicit or file
  tribo::ContactCoefficients values;     // keyword block
  tribo::ContactParameters parameters;   // explicit and file forms, the wall's value groups
};

// pair_coeff I J <form>: arg[0..narg), the form from arg[2].
inline Read read_pair_coeff(const Host &host, int narg, char **arg, tribo::ContactModelChoice &choice)
{
  Read r;
  if (narg >= 3 && !host.is_number(arg[2]) && !number_like(arg[2]) && std::strcmp(arg[2], "file") != 0) {
    r.origin = "keywords";
    int iarg = 2;
    r.values = read_blocks(host, narg, arg, iarg, choice, true, false);
    return r;
  }
  int first = narg;
  if (narg >= 6 && std::strcmp(arg[2], "file") == 0) {
    r.origin = "file";
    r.parameters = host.material(arg[3], arg[4], arg[5]);
    first = 6;
  } else if (narg == 2 + kExplicitValues || (narg > 2 + kExplicitValues && !host.is_number(arg[2 + kExplicitValues]))) {
    for (int k = 0; k < kExplicitValues; k++)
      set_named(r.parameters, kExplicitNames[k], number(host, host.style, kExplicitNames[k], arg[2 + k]));
    // explicit values give no yield strength: Tabor's, unless the S_y option follows
    yield_from_hardness(r.parameters);
    first = 2 + kExplicitValues;
  } else if (narg >= 3 && std::strcmp(arg[2], "file") == 0) {
    fail(host, fmt::format("{}: 'file' takes a path and two material names ('I J file <path> <material-I> "
                           "<material-J>'), got {} value(s)", host.style, narg - 3));
  } else {
    // count the numbers given after the type pair, and name the positional values left out
    int given = 0;
    while (2 + given < narg && host.is_number(arg[2 + given])) given++;
    std::string problem;
    if (given >= kExplicitValues)
      problem = fmt::format(" ({} too many)", given - kExplicitValues);
    else
      problem = fmt::format(" (missing: {})", joined(kExplicitNames + given, kExplicitNames + kExplicitValues));
    fail(host, fmt::format("{}: expected 'I J E* G* e mu_s mu_k d_c k H' (8 values after the type pair), got {} "
                           "value(s){}; or 'I J file <path> <material-I> <material-J>', then optional 'tau_s X' "
                           "'plough X', or 'I J normal NAME values ... damping ... tangential ... friction ... wear ...'",
                           host.style, given, problem));
  }
  read_options(host, r.parameters, narg, arg, first);
  return r;
}

// The checks every form passes, once: the named parameters onto the chosen sub-models (refusing what the models need
// and the deck left out), the contact model's validation, the keyword block's tau_s against its S_y, and Tabor's
// fallback WARNING. `where` prefixes the kernels' messages; `subject` and `yield_hint` word the WARNING.
inline tribo::ContactCoefficients checked(const Host &host, const Read &r, const tribo::ContactModelChoice &choice,
                                          const tribo::ContactSettings &settings, const std::string &where,
                                          const std::string &subject, const char *yield_hint)
{
  const bool keywords = r.origin == std::string("keywords");
  const tribo::ContactCoefficients c =
      keywords ? r.values : kernel(host, where, [&] { return tribo::contact_coefficients(choice, r.parameters); });
  kernel(host, where, [&] { tribo::ContactModel(choice, c, settings); });
  using K = tribo::SubModelKind;
  const double *yield = named_coefficient(choice, c, K::normal, "S_y");
  // the other forms check an adhesion law's tau_s against the materials' S_y in contact_coefficients
  if (keywords && yield)
    if (const double *tau_s = named_coefficient(choice, c, K::friction, "tau_s"))
      kernel(host, where, [&] { tribo::check_interface_strength(*tau_s, *yield); });
  const tribo::ContactParameters &p = r.parameters;
  if (!keywords && yield && p.yield_from_hardness && p.yield_strength > 0.0)
    host.warning(fmt::format("{}: no yield strength given ({} or material file): S_y = H / {} = {:.4g} Pa (Tabor), "
                             "nu = {}", subject, yield_hint, tribo::kTaborConstraintFactor, p.yield_strength,
                             p.poisson_ratio));
  return c;
}

// pair_coeff I J ...: read and checked, messages "<style> (<form>): ..." and the WARNING naming the type pair.
inline tribo::ContactCoefficients pair_coeff(const Host &host, int narg, char **arg, tribo::ContactModelChoice &choice,
                                             const tribo::ContactSettings &settings)
{
  const Read read = read_pair_coeff(host, narg, arg, choice);
  return checked(host, read, choice, settings, fmt::format("{} ({})", host.style, read.origin),
                 fmt::format("{} {} {}", host.style, arg[0], arg[1]), "S_y keyword");
}

// pair_coeff's type pairs I <= J in the ranges ilo..ihi, jlo..jhi (the host's bounds of arg[0], arg[1]): c for I,J,
// as seen from J for J,I, marked set; none in range is an ERROR.
template <class CoeffOf>
void store_type_pairs(const Host &host, char **arg, int ilo, int ihi, int jlo, int jhi,
                      const tribo::ContactModelChoice &choice, const tribo::ContactCoefficients &c, CoeffOf coeff_of,
                      int **setflag)
{
  int count = 0;
  for (int i = ilo; i <= ihi; i++)
    for (int j = std::max(jlo, i); j <= jhi; j++) {
      coeff_of(i, j) = c;
      coeff_of(j, i) = tribo::swap_bodies(choice, c);
      setflag[i][j] = 1;
      count++;
    }
  if (count == 0) fail(host, fmt::format("{}: no type pair in range {} {}", host.style, arg[0], arg[1]));
}

}    // namespace runin_coeff

#endif
