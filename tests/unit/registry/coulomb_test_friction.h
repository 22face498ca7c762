// TEST-ONLY friction law, never in the shipped registry: constant-mu Coulomb, F_t <= mu F_n. It proves that a new
// friction law is one class and one registry row (doc/architecture.md, "One contact model, and how to add a law").
// The test build includes this file at the registry of src/tribo/contact_model.h (inside namespace runin::tribo,
// -DRUNIN_TEST_SUB_MODELS="coulomb_test_friction.h"); RUNIN_TEST_FRICTION_MODELS is its registry row.
class CoulombTestFrictionModel {
 public:
  static constexpr const char *name = "coulomb_test";
  static constexpr std::array<const char *, 1> coefficient_names{"mu"};
  // the explicit and file forms: their kinetic friction coefficient
  template <class P> static Coefficients from_parameters(const P &p) { return {p.mu_kinetic}; }
  explicit CoulombTestFrictionModel(const double *c) : mu_(c[0])
  {
    if (!(c[0] >= 0.0)) throw InvalidCoefficient("mu: friction coefficient must be >= 0");
  }
  Coefficients values() const { return {mu_}; }
  static Coefficients mix(const Coefficients &ii, const Coefficients &jj) { return {mix_geometric(ii[0], jj[0])}; }
  double limit(double, double normal_force, const NormalContact &, double, FrictionStrengthParts &) const
  {
    return mu_ * normal_force;
  }

 private:
  double mu_;
};
#define RUNIN_TEST_FRICTION_MODELS , CoulombTestFrictionModel
