#include "tribo/contact_model.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

namespace runin::tribo {

namespace {

template <class Model, class = void> struct CitationsOf {
  static std::vector<const char *> get() { return {}; }
};
template <class Model> struct CitationsOf<Model, std::void_t<decltype(Model::citations)>> {
  static std::vector<const char *> get() { return {Model::citations.begin(), Model::citations.end()}; }
};

template <class Tuple, std::size_t... I>
std::vector<SubModelInfo> infos_of(std::index_sequence<I...>)
{
  std::vector<SubModelInfo> out;
  (out.push_back(SubModelInfo{
       std::tuple_element_t<I, Tuple>::name,
       std::vector<const char *>(std::tuple_element_t<I, Tuple>::coefficient_names.begin(),
                                 std::tuple_element_t<I, Tuple>::coefficient_names.end()),
       FlattensSummits<std::tuple_element_t<I, Tuple>>::value, HasFilm<std::tuple_element_t<I, Tuple>>::value,
       InterfaceUseOf<std::tuple_element_t<I, Tuple>>::value, CitationsOf<std::tuple_element_t<I, Tuple>>::get()}),
   ...);
  return out;
}
template <class Tuple> std::vector<SubModelInfo> infos_of()
{
  return infos_of<Tuple>(std::make_index_sequence<std::tuple_size_v<Tuple>>{});
}

// Builds the chosen alternative (index) of a kind in its slot; the constructor validates.
template <class Tuple, class Slots, std::size_t... I, class... Args>
void emplace_chosen(Slots &slots, int index, std::index_sequence<I...>, const Args &...args)
{
  ((index == static_cast<int>(I) ? (void)std::get<I>(slots).emplace(args...) : void()), ...);
}
template <class Tuple, class Slots, class... Args> void emplace_chosen(Slots &slots, int index, const Args &...args)
{
  emplace_chosen<Tuple>(slots, index, std::make_index_sequence<std::tuple_size_v<Tuple>>{}, args...);
}

template <class Tuple, std::size_t... I>
Coefficients mix_chosen(int index, const Coefficients &ii, const Coefficients &jj, std::index_sequence<I...>)
{
  Coefficients out;
  ((index == static_cast<int>(I) ? (void)(out = std::tuple_element_t<I, Tuple>::mix(ii, jj)) : void()), ...);
  return out;
}
template <class Tuple> Coefficients mix_chosen(int index, const Coefficients &ii, const Coefficients &jj)
{
  return mix_chosen<Tuple>(index, ii, jj, std::make_index_sequence<std::tuple_size_v<Tuple>>{});
}

template <class Tuple, class P, std::size_t... I>
Coefficients from_parameters_chosen(int index, const P &p, std::index_sequence<I...>)
{
  Coefficients out;
  ((index == static_cast<int>(I) ? (void)(out = std::tuple_element_t<I, Tuple>::from_parameters(p)) : void()), ...);
  return out;
}
template <class Tuple, class P> Coefficients from_parameters_chosen(int index, const P &p)
{
  return from_parameters_chosen<Tuple>(index, p, std::make_index_sequence<std::tuple_size_v<Tuple>>{});
}

// f(model) for the one set slot of a kind
template <class Slots, class F> void with_set(const Slots &slots, F &&f)
{
  std::apply([&](const auto &...slot) { ((slot ? (void)f(*slot) : void()), ...); }, slots);
}

// Names are stored in restart records as their characters, one double each (exact for 0..255).
constexpr double kRecordMark = 7.0e77;    // first value of a record: not a count, not a character
constexpr int kRecordVersion = 1;

}    // namespace

namespace {
template <std::size_t... I> int history_size_of(int normal_index, std::index_sequence<I...>)
{
  int out = TANGENTIAL_HISTORY_SIZE;
  ((normal_index == static_cast<int>(I) ? (void)(out = contact_history_size<I>) : void()), ...);
  return out;
}
}    // namespace

int contact_history_size_of(int normal_index)
{
  return history_size_of(normal_index, std::make_index_sequence<std::tuple_size_v<NormalModels>>{});
}

const char *sub_model_kind_name(SubModelKind kind)
{
  static const char *const names[kSubModelKinds] = {"normal", "damping", "tangential", "friction", "wear"};
  return names[static_cast<int>(kind)];
}

const std::vector<SubModelInfo> &registered_sub_models(SubModelKind kind)
{
  static const std::array<std::vector<SubModelInfo>, kSubModelKinds> table = {
      infos_of<NormalModels>(), infos_of<DampingModels>(), infos_of<TangentialModels>(),
      infos_of<FrictionModels>(), infos_of<WearModels>()};
  return table[static_cast<int>(kind)];
}

std::string registered_names(SubModelKind kind)
{
  const auto &models = registered_sub_models(kind);
  std::string out;
  for (std::size_t k = 0; k < models.size(); ++k) out += (k ? ", " : "") + std::string(models[k].name);
  return out;
}

int find_sub_model(SubModelKind kind, const std::string &name)
{
  const auto &models = registered_sub_models(kind);
  for (std::size_t k = 0; k < models.size(); ++k)
    if (name == models[k].name) return static_cast<int>(k);
  throw InvalidCoefficient(std::string("unknown ") + sub_model_kind_name(kind) + " model '" + name +
                           "' (known: " + registered_names(kind) + ")");
}

std::vector<std::string> interface_friction_models()
{
  std::vector<std::string> out;
  for (const SubModelInfo &info : registered_sub_models(SubModelKind::friction))
    if (info.interface_use != InterfaceUse::none) out.push_back(info.name);
  return out;
}

std::string default_interface_friction_model()
{
  for (const SubModelInfo &info : registered_sub_models(SubModelKind::friction))
    if (info.interface_use == InterfaceUse::shear_strength) return info.name;
  return {};
}

Coefficients friction_coefficients_from(int index, const ContactParameters &p)
{
  return from_parameters_chosen<FrictionModels>(index, p);
}

void check_coefficient_counts(const ContactModelChoice &choice, const ContactCoefficients &coefficients)
{
  for (int k = 0; k < kSubModelKinds; ++k) {
    const auto kind = static_cast<SubModelKind>(k);
    const SubModelInfo &info = registered_sub_models(kind)[choice.of(kind)];
    const int got = static_cast<int>(coefficients.of(kind).size());
    if (got == info.coefficient_count()) continue;
    std::string names;
    for (const char *n : info.coefficient_names) names += (names.empty() ? "" : " ") + std::string(n);
    throw InvalidCoefficient(std::string(sub_model_kind_name(kind)) + " model '" + info.name + "' takes " +
                             std::to_string(info.coefficient_count()) + " coefficient(s) (" + names + "), got " +
                             std::to_string(got));
  }
}

void check_coefficients(const ContactModelChoice &choice, const ContactCoefficients &coefficients)
{
  check_coefficient_counts(choice, coefficients);
  for (int k = 0; k < kSubModelKinds; ++k) {
    const auto kind = static_cast<SubModelKind>(k);
    const SubModelInfo &info = registered_sub_models(kind)[choice.of(kind)];
    const Coefficients &values = coefficients.of(kind);
    for (std::size_t n = 0; n < values.size(); ++n)
      if (!std::isfinite(values[n]))
        throw InvalidCoefficient(std::string(info.coefficient_names[n]) + ": must be a finite number, got " +
                                 (std::isnan(values[n]) ? "nan" : "inf"));
  }
}

ContactCoefficients mix_coefficients(const ContactModelChoice &choice, const ContactCoefficients &ii,
                                     const ContactCoefficients &jj)
{
  check_coefficient_counts(choice, ii);
  check_coefficient_counts(choice, jj);
  ContactCoefficients out;
  using K = SubModelKind;
  out.of(K::normal) = mix_chosen<NormalModels>(choice.of(K::normal), ii.of(K::normal), jj.of(K::normal));
  out.of(K::damping) = mix_chosen<DampingModels>(choice.of(K::damping), ii.of(K::damping), jj.of(K::damping));
  out.of(K::tangential) =
      mix_chosen<TangentialModels>(choice.of(K::tangential), ii.of(K::tangential), jj.of(K::tangential));
  out.of(K::friction) =
      mix_chosen<FrictionModels>(choice.of(K::friction), ii.of(K::friction), jj.of(K::friction));
  out.of(K::wear) = mix_chosen<WearModels>(choice.of(K::wear), ii.of(K::wear), jj.of(K::wear));
  return out;
}

// Record: mark, version, kinds; per kind: name length, name characters, count, values.
std::vector<double> serialize(const ContactModelChoice &choice, const ContactCoefficients &coefficients)
{
  check_coefficient_counts(choice, coefficients);
  std::vector<double> out{kRecordMark, static_cast<double>(kRecordVersion), static_cast<double>(kSubModelKinds)};
  for (int k = 0; k < kSubModelKinds; ++k) {
    const auto kind = static_cast<SubModelKind>(k);
    const char *name = registered_sub_models(kind)[choice.of(kind)].name;
    const std::size_t length = std::strlen(name);
    out.push_back(static_cast<double>(length));
    for (std::size_t c = 0; c < length; ++c) out.push_back(static_cast<unsigned char>(name[c]));
    const Coefficients &values = coefficients.of(kind);
    out.push_back(static_cast<double>(values.size()));
    out.insert(out.end(), values.begin(), values.end());
  }
  return out;
}

std::pair<ContactModelChoice, ContactCoefficients> deserialize(const double *record, int size)
{
  int at = 0;
  auto next = [&](const char *what) {
    if (at >= size) throw InvalidCoefficient(std::string("contact model record ends before its ") + what);
    return record[at++];
  };
  auto count = [&](const char *what, int most) {
    const double v = next(what);
    if (!(v >= 0.0 && v <= most) || v != std::floor(v))
      throw InvalidCoefficient(std::string("contact model record: bad ") + what);
    return static_cast<int>(v);
  };
  if (next("mark") != kRecordMark)
    throw InvalidCoefficient("contact model record: not a RunIn contact model (written by an older version?)");
  if (count("version", 1000) != kRecordVersion)
    throw InvalidCoefficient("contact model record: unknown version");
  if (count("kind count", 100) != kSubModelKinds) throw InvalidCoefficient("contact model record: kind count");
  ContactModelChoice choice;
  ContactCoefficients coefficients;
  for (int k = 0; k < kSubModelKinds; ++k) {
    const auto kind = static_cast<SubModelKind>(k);
    const int length = count("name length", 64);
    std::string name;
    for (int c = 0; c < length; ++c) name.push_back(static_cast<char>(count("name", 255)));
    choice.index[k] = find_sub_model(kind, name);
    const int n = count("coefficient count", 64);
    for (int c = 0; c < n; ++c) coefficients.of(kind).push_back(next("coefficients"));
  }
  check_coefficient_counts(choice, coefficients);
  return {choice, coefficients};
}

std::string describe(const ContactModelChoice &choice)
{
  std::string out;
  for (int k = 0; k < kSubModelKinds; ++k) {
    const auto kind = static_cast<SubModelKind>(k);
    out += (k ? " " : "") + std::string(sub_model_kind_name(kind)) + " " +
           registered_sub_models(kind)[choice.of(kind)].name;
  }
  return out;
}

std::string describe_difference(const ContactModelChoice &stored, const ContactModelChoice &current)
{
  std::string out;
  for (int k = 0; k < kSubModelKinds; ++k) {
    const auto kind = static_cast<SubModelKind>(k);
    if (stored.of(kind) == current.of(kind)) continue;
    out += (out.empty() ? "" : "; ") + std::string(sub_model_kind_name(kind)) + " model: restart '" +
           registered_sub_models(kind)[stored.of(kind)].name + "', input '" +
           registered_sub_models(kind)[current.of(kind)].name + "'";
  }
  return out;
}

ContactModel::ContactModel(const ContactModelChoice &choice, const ContactCoefficients &c,
                           const ContactSettings &settings)
    : choice_(choice), restick_speed_(settings.restick_speed)
{
  check_coefficients(choice, c);
  using K = SubModelKind;
  // the materials' hardness first: the elastic-plastic yield strength may have been derived from it
  emplace_chosen<WearModels>(wear_, choice.of(K::wear), c.of(K::wear).data(), settings.archard_form,
                             settings.transfer_fraction);
  emplace_chosen<NormalModels>(normal_, choice.of(K::normal), c.of(K::normal).data());
  emplace_chosen<DampingModels>(damping_, choice.of(K::damping), c.of(K::damping).data());
  emplace_chosen<TangentialModels>(tangential_, choice.of(K::tangential), c.of(K::tangential).data());
  emplace_chosen<FrictionModels>(friction_, choice.of(K::friction), c.of(K::friction).data());
  if (!(settings.restick_speed >= 0.0) || !std::isfinite(settings.restick_speed))
    throw InvalidCoefficient("restick: speed must be >= 0 m/s and finite");
  // the friction law's own checks against the chosen normal and wear laws (check_with)
  with_set(friction_, [&](const auto &friction) {
    using Friction = std::decay_t<decltype(friction)>;
    with_set(normal_, [&](const auto &normal) {
      with_set(wear_, [&](const auto &wear) {
        if constexpr (HasCrossCheck<Friction, std::decay_t<decltype(normal)>, std::decay_t<decltype(wear)>>::value)
          friction.check_with(normal, wear);
      });
    });
  });
}

double ContactModel::effective_modulus() const
{
  double out = 0.0;
  std::apply([&](const auto &...slot) { ((slot ? (void)(out = slot->effective_modulus()) : void()), ...); },
             normal_);
  return out;
}

}    // namespace runin::tribo

namespace runin::tribo {

ContactParameters contact_parameters(const Material &i, const Material &j, double restitution, double mu_static,
                                     double mu_kinetic, double slip_weakening_distance, double wear_coefficient)
{
  ContactParameters p;
  p.effective_modulus = effective_modulus(i, j);
  p.effective_shear_modulus = effective_shear_modulus(i, j);
  p.restitution = restitution;
  p.mu_static = mu_static;
  p.mu_kinetic = mu_kinetic;
  p.slip_weakening_distance = slip_weakening_distance;
  p.wear_coefficient = wear_coefficient;
  p.hardness_i = i.hardness;
  p.hardness_j = j.hardness;
  // the softer body yields first: its S_y (Tabor's H / 2.8 where none is given) and nu
  auto yield_of = [](const Material &m) {
    return m.yield_strength > 0.0 ? m.yield_strength : tabor_yield_strength(m.hardness);
  };
  const Material &soft = yield_of(i) <= yield_of(j) ? i : j;
  p.yield_strength = yield_of(soft);
  p.poisson_ratio = soft.poisson_ratio;
  p.yield_from_hardness = !(soft.yield_strength > 0.0);
  return p;
}

namespace {
// "a" or "a or b": the friction laws with a film
std::string film_models()
{
  std::string out;
  for (const SubModelInfo &info : registered_sub_models(SubModelKind::friction))
    if (info.has_film) out += (out.empty() ? "" : " or ") + std::string(info.name);
  return out;
}
// "'a'", "'a' and 'b'", "'a', 'b' and 'c'": the friction laws an interface state sets `use` of
std::string friction_models_using(InterfaceUse use)
{
  std::vector<std::string> names;
  for (const SubModelInfo &info : registered_sub_models(SubModelKind::friction))
    if (info.interface_use == use) names.push_back("'" + std::string(info.name) + "'");
  std::string out;
  for (std::size_t k = 0; k < names.size(); ++k)
    out += (k == 0 ? "" : k + 1 == names.size() ? " and " : ", ") + names[k];
  return out;
}
}    // namespace

ContactCoefficients contact_coefficients(const ContactModelChoice &choice, const ContactParameters &given)
{
  using K = SubModelKind;
  ContactCoefficients c;
  c.of(K::normal) = from_parameters_chosen<NormalModels>(choice.of(K::normal), given);
  c.of(K::damping) = from_parameters_chosen<DampingModels>(choice.of(K::damping), given);
  c.of(K::tangential) = from_parameters_chosen<TangentialModels>(choice.of(K::tangential), given);
  const SubModelInfo &friction_info = registered_sub_models(K::friction)[choice.of(K::friction)];
  const std::string friction = friction_info.name;
  const bool adhesion_law = friction_info.interface_use == InterfaceUse::shear_strength;
  // S_y given (material file or keyword), not Tabor's H / 2.8 guess
  const bool yield_known = !given.yield_from_hardness && given.yield_strength > 0.0;
  // the interface state resolved into the value it sets (tau_s or f)
  ContactParameters p = given;
  if (p.interface_state >= 0) {
    const std::string state = kInterfaceStateNames[p.interface_state];
    const double m = p.interface_factors[p.interface_state];
    if (std::isnan(m))
      throw InvalidCoefficient("interface: no friction factor m for state '" + state + "' of this material pair (a "
                               "coefficient file line 'interface A B " + state + " m'; the file form reads it)");
    if (adhesion_law) {
      if (p.shear_strength != 0.0)
        throw InvalidCoefficient("interface: give either tau_s or interface " + state + ", not both");
      if (!yield_known)
        throw InvalidCoefficient("interface: tau_s = m S_y / sqrt(3) needs the yield strength of the softer body, not "
                                 "Tabor's H / 2.8 (the material's 6th value in the coefficient file)");
      p.shear_strength = interface_shear_strength(m, p.yield_strength);
    } else if (friction_info.interface_use == InterfaceUse::interface_coefficient) {
      if (!std::isnan(p.interface_coefficient))
        throw InvalidCoefficient("interface: give either f or interface " + state + ", not both");
      p.interface_coefficient = m;
    } else {
      throw InvalidCoefficient("interface: friction model '" + friction + "' has no interface strength (interface " +
                               state + " sets tau_s of " + friction_models_using(InterfaceUse::shear_strength) +
                               " or f of " + friction_models_using(InterfaceUse::interface_coefficient) + ")");
    }
  }
  // an interface stronger than the softer body's shear yield; above the hardness ContactModel says so first
  if (adhesion_law && yield_known && p.shear_strength <= std::min(p.hardness_i, p.hardness_j))
    check_interface_strength(p.shear_strength, p.yield_strength);
  c.of(K::friction) = from_parameters_chosen<FrictionModels>(choice.of(K::friction), p);
  // a film's values on a pair whose friction model has none would be ignored: refused
  if (!friction_info.has_film) {
    const char *film_value = !std::isnan(p.film_interface_coefficient) ? "f_film"
                             : !std::isnan(p.film_removal_distance)    ? "s_r"
                             : !std::isnan(p.film_growth_rate)         ? "k_g"
                                                                       : nullptr;
    if (film_value)
      throw InvalidCoefficient(std::string(film_value) + ": friction model '" + friction +
                               "' has no surface film (film keywords need friction " + film_models() + ")");
  }
  c.of(K::wear) = from_parameters_chosen<WearModels>(choice.of(K::wear), p);
  check_coefficient_counts(choice, c);
  return c;
}

namespace {
// A law with per-body coefficients says how they swap (static swap_bodies); the others' are the pair's.
template <class Model, class = void> struct HasBodySwap : std::false_type {};
template <class Model>
struct HasBodySwap<Model, std::void_t<decltype(Model::swap_bodies(std::declval<const Coefficients &>()))>>
    : std::true_type {};
template <class Tuple, std::size_t... I>
Coefficients swap_chosen(int index, const Coefficients &c, std::index_sequence<I...>)
{
  Coefficients out = c;
  const auto swap = [&](auto *model) {
    using Model = std::remove_pointer_t<decltype(model)>;
    if constexpr (HasBodySwap<Model>::value) out = Model::swap_bodies(c);
  };
  ((index == static_cast<int>(I) ? swap(static_cast<std::tuple_element_t<I, Tuple> *>(nullptr)) : void()), ...);
  return out;
}
template <class Tuple> Coefficients swap_chosen(int index, const Coefficients &c)
{
  return swap_chosen<Tuple>(index, c, std::make_index_sequence<std::tuple_size_v<Tuple>>{});
}
}    // namespace

ContactCoefficients swap_bodies(const ContactModelChoice &choice, const ContactCoefficients &c)
{
  using K = SubModelKind;
  ContactCoefficients out;
  out.of(K::normal) = swap_chosen<NormalModels>(choice.of(K::normal), c.of(K::normal));
  out.of(K::damping) = swap_chosen<DampingModels>(choice.of(K::damping), c.of(K::damping));
  out.of(K::tangential) = swap_chosen<TangentialModels>(choice.of(K::tangential), c.of(K::tangential));
  out.of(K::friction) = swap_chosen<FrictionModels>(choice.of(K::friction), c.of(K::friction));
  out.of(K::wear) = swap_chosen<WearModels>(choice.of(K::wear), c.of(K::wear));
  return out;
}

}    // namespace runin::tribo
