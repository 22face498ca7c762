#include "tribo/contact_model.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

namespace runin::tribo {

namespace {

template <class Tuple, std::size_t... I>
std::vector<SubModelInfo> infos_of(std::index_sequence<I...>)
{
  std::vector<SubModelInfo> out;
  (out.push_back(SubModelInfo{
       std::tuple_element_t<I, Tuple>::name,
       std::vector<const char *>(std::tuple_element_t<I, Tuple>::coefficient_names.begin(),
                                 std::tuple_element_t<I, Tuple>::coefficient_names.end())}),
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

int find_sub_model(SubModelKind kind, const std::string &name)
{
  const auto &models = registered_sub_models(kind);
  std::string known;
  for (std::size_t k = 0; k < models.size(); ++k) {
    if (name == models[k].name) return static_cast<int>(k);
    known += (k ? ", " : "") + std::string(models[k].name);
  }
  throw InvalidCoefficient(std::string("unknown ") + sub_model_kind_name(kind) + " model '" + name +
                           "' (known: " + known + ")");
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
  // a film at the interface cannot shear harder than the bulk under it
  const auto &archard = std::get<std::optional<ArchardWearModel>>(wear_);
  const double softer = std::min(archard->body_i().hardness(), archard->body_j().hardness());
  const auto check_film = [softer](const auto &model) {
    if (!model || model->shear_strength() <= softer) return;
    char message[160];
    std::snprintf(message, sizeof message,
                  "tau_s: interfacial shear strength %.4g Pa exceeds the hardness of the softer body, %.4g Pa",
                  model->shear_strength(), softer);
    throw InvalidCoefficient(message);
  };
  check_film(std::get<std::optional<StrengthFrictionModel>>(friction_));
  check_film(std::get<std::optional<BrizmerFrictionModel>>(friction_));
  // junction growth needs the plastic history and mean pressure of the elastic-plastic model
  if (std::get<std::optional<JunctionFrictionModel>>(friction_) &&
      !std::get<std::optional<ElasticPlasticNormalModel>>(normal_))
    throw InvalidCoefficient("friction model 'junction' needs the normal model 'elastic/plastic'");
  if (std::get<std::optional<JunctionFilmFrictionModel>>(friction_) &&
      !std::get<std::optional<ElasticPlasticNormalModel>>(normal_))
    throw InvalidCoefficient("friction model 'junction/film' needs the normal model 'elastic/plastic'");
  if (std::get<std::optional<BrizmerFrictionModel>>(friction_)) {
    const auto &plastic = std::get<std::optional<ElasticPlasticNormalModel>>(normal_);
    if (!plastic)
      throw InvalidCoefficient("friction model 'brizmer' needs the normal model 'elastic/plastic'");
    const double nu = plastic->unit_curve().coefficients().poisson_ratio;
    if (!(nu >= 0.2 && nu < 0.5))
      throw InvalidCoefficient("nu: friction model 'brizmer' is fitted for a Poisson ratio in [0.2, 0.5), got " +
                               std::to_string(nu));
  }
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

ContactCoefficients contact_coefficients(const ContactModelChoice &choice, const ContactParameters &p)
{
  using K = SubModelKind;
  ContactCoefficients c;
  const std::string normal = registered_sub_models(K::normal)[choice.of(K::normal)].name;
  if (normal == HertzNormalModel::name) c.of(K::normal) = {p.effective_modulus};
  if (normal == ElasticPlasticNormalModel::name) c.of(K::normal) = {p.effective_modulus, p.yield_strength, p.poisson_ratio};
  c.of(K::damping) = {p.restitution};
  c.of(K::tangential) = {p.effective_shear_modulus};
  const std::string friction = registered_sub_models(K::friction)[choice.of(K::friction)].name;
  const bool adhesion_law = friction == StrengthFrictionModel::name || friction == BrizmerFrictionModel::name;
  // S_y given (material file or keyword), not Tabor's H / 2.8 guess
  const bool yield_known = !p.yield_from_hardness && p.yield_strength > 0.0;
  double shear_strength = p.shear_strength, interface_coefficient = p.interface_coefficient;
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
      shear_strength = interface_shear_strength(m, p.yield_strength);
    } else if (friction == JunctionFrictionModel::name) {
      if (!std::isnan(p.interface_coefficient))
        throw InvalidCoefficient("interface: give either f or interface " + state + ", not both");
      interface_coefficient = m;
    } else {
      throw InvalidCoefficient("interface: friction model '" + friction + "' has no interface strength (interface " +
                               state + " sets tau_s of 'strength' and 'brizmer' or f of 'junction')");
    }
  }
  // an interface stronger than the softer body's shear yield; above the hardness ContactModel says so first
  if (adhesion_law && yield_known && shear_strength <= std::min(p.hardness_i, p.hardness_j))
    check_interface_strength(shear_strength, p.yield_strength);
  if (friction == CoulombFrictionModel::name)
    c.of(K::friction) = {p.mu_static, p.mu_kinetic, p.slip_weakening_distance};
  else if (friction == StrengthFrictionModel::name)
    c.of(K::friction) = {p.mu_static, p.mu_kinetic, p.slip_weakening_distance, shear_strength,
                         p.ploughing_factor};
  else if (friction == BrizmerFrictionModel::name)
    c.of(K::friction) = {p.slip_weakening_distance, shear_strength, p.ploughing_factor};
  else if (friction == JunctionFrictionModel::name) {
    // which contacts are plastic junctions follows from S_y: Tabor's H / 2.8 guess is not taken for it
    if (p.yield_from_hardness)
      throw InvalidCoefficient("S_y: friction model 'junction' needs the yield strength of the softer body, not "
                               "Tabor's H / 2.8 (pair_coeff keyword 'S_y X', fix runin/wall keyword 'yield', or "
                               "the material's 6th value in a coefficient file)");
    if (std::isnan(interface_coefficient))
      throw InvalidCoefficient("f: friction model 'junction' needs the interface coefficient f, 0 <= f < 1 "
                               "(pair_coeff keyword 'f X', fix runin/wall keyword 'junction f alpha')");
    c.of(K::friction) = {interface_coefficient, p.junction_alpha};
  }
  else if (friction == JunctionFilmFrictionModel::name) {
    if (p.yield_from_hardness)
      throw InvalidCoefficient("S_y: friction model 'junction/film' needs the yield strength of the softer body, "
                               "not Tabor's H / 2.8 (pair_coeff keyword 'S_y X' or the material's 6th value in a "
                               "coefficient file)");
    if (std::isnan(p.interface_coefficient))
      throw InvalidCoefficient("f: friction model 'junction/film' needs the clean interface coefficient f, "
                               "0 <= f < 1 (pair_coeff keyword 'f X')");
    if (std::isnan(p.film_interface_coefficient))
      throw InvalidCoefficient("f_film: friction model 'junction/film' needs the film's interface coefficient, "
                               "0 <= f_film < 1 (pair_coeff keyword 'f_film X')");
    const auto off_unless_given = [](double v) { return std::isnan(v) ? 0.0 : v; };
    c.of(K::friction) = {p.interface_coefficient, p.film_interface_coefficient, p.junction_alpha,
                         off_unless_given(p.film_removal_distance), off_unless_given(p.film_growth_rate)};
  }
  // a film's values on a pair whose friction model has none would be ignored: refused
  if (friction != JunctionFilmFrictionModel::name) {
    const char *given = !std::isnan(p.film_interface_coefficient) ? "f_film"
                        : !std::isnan(p.film_removal_distance)    ? "s_r"
                        : !std::isnan(p.film_growth_rate)         ? "k_g"
                                                                  : nullptr;
    if (given)
      throw InvalidCoefficient(std::string(given) + ": friction model '" + friction +
                               "' has no surface film (film keywords need friction junction/film)");
  }
  c.of(K::wear) = {p.wear_coefficient, p.hardness_i, p.wear_coefficient, p.hardness_j};
  check_coefficient_counts(choice, c);
  return c;
}

ContactCoefficients swap_bodies(const ContactModelChoice &choice, const ContactCoefficients &c)
{
  // only the wear law has per-body coefficients so far
  static_assert(std::tuple_size_v<WearModels> == 1, "swap the per-body coefficients of every wear law");
  ContactCoefficients out = c;
  (void) choice;
  out.of(SubModelKind::wear) = ArchardWearModel::swap_bodies(c.of(SubModelKind::wear));
  return out;
}

}    // namespace runin::tribo
