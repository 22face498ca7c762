// Compiled (syntax only) by ctest registry.friction_history_slots_refused: the registry with a friction law that
// declares history slots (friction_with_history.h) must not compile.
#define RUNIN_TEST_SUB_MODELS "friction_with_history.h"
#include "tribo/contact_model.h"
