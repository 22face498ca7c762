// Prints the registry's names per kind, one line each ("KIND: NAME, NAME, ..."), as the "known: ..."
// of the hosts' messages lists them: the test runners put them into the expected ERROR patterns
// ({registry:KIND}, tests/lammps/run_deck.py), so adding a registry row needs no test edit.
#include <cstdio>

#include "tribo/contact_model.h"

int main()
{
  using runin::tribo::SubModelKind;
  for (int k = 0; k < runin::tribo::kSubModelKinds; ++k) {
    const auto kind = static_cast<SubModelKind>(k);
    std::printf("%s: %s\n", runin::tribo::sub_model_kind_name(kind), runin::tribo::registered_names(kind).c_str());
  }
  return 0;
}
