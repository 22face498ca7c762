// TEST-ONLY: a friction law that declares a history slot, which the registry does not place for the friction kind;
// the build must stop with the registry's static_assert (ctest registry.friction_history_slots_refused), not ignore
// the slot. Included at the registry like coulomb_test_friction.h: its Coulomb law plus the slot, registered instead.
#include "coulomb_test_friction.h"

class SlotTestFrictionModel : public CoulombTestFrictionModel {
 public:
  static constexpr const char *name = "slot_test";
  static constexpr int history_slots = 1;
  using CoulombTestFrictionModel::CoulombTestFrictionModel;
};
#undef RUNIN_TEST_FRICTION_MODELS
#define RUNIN_TEST_FRICTION_MODELS , SlotTestFrictionModel
