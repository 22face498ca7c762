// TEST-ONLY: a friction law that declares a history slot, which the registry does not place for the friction kind;
// the build must stop with the registry's static_assert (ctest registry.friction_history_slots_refused), not ignore
// the slot. Included at the registry like coulomb_test_friction.h.
class SlotTestFrictionModel {
 public:
  static constexpr const char *name = "slot_test";
  static constexpr std::array<const char *, 1> coefficient_names{"mu"};
  static constexpr int history_slots = 1;
  template <class P> static Coefficients from_parameters(const P &p) { return {p.mu_kinetic}; }
  explicit SlotTestFrictionModel(const double *c) : mu_(c[0]) {}
  Coefficients values() const { return {mu_}; }
  static Coefficients mix(const Coefficients &ii, const Coefficients &jj) { return {mix_geometric(ii[0], jj[0])}; }
  double limit(double, double normal_force, const NormalContact &, double, FrictionStrengthParts &) const
  {
    return mu_ * normal_force;
  }

 private:
  double mu_;
};
#define RUNIN_TEST_FRICTION_MODELS , SlotTestFrictionModel
