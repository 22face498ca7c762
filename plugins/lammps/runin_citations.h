// The papers of the contact models a RunIn style runs, for LAMMPS's log.cite (CiteMe). Each entry's first line is
// what LAMMPS prints in its terse summary; the rest is BibTeX.
#pragma once

#include "tribo/contact_model.h"

#include <string>
#include <vector>

namespace runin_lammps {

inline const char *const kCiteGreenwoodWilliamson =
    "RunIn fix runin/wall (rough on flat): Greenwood and Williamson (1966)\n\n"
    "@Article{GreenwoodWilliamson1966,\n author = {J. A. Greenwood and J. B. P. Williamson},\n title = {Contact of "
    "nominally flat surfaces},\n journal = {Proceedings of the Royal Society of London A},\n year = 1966,\n"
    " volume = 295,\n pages = {300--319}\n}\n\n";

// The entries the sub-models in `choice` declare (SubModelInfo::citations); `wear`: wear is on; `wall`: the
// rough-on-flat wall.
inline std::vector<const char *> model_citations(const runin::tribo::ContactModelChoice &choice, bool wear, bool wall)
{
  using runin::tribo::SubModelKind;
  std::vector<const char *> entries;
  for (int k = 0; k < runin::tribo::kSubModelKinds; k++) {
    const auto kind = static_cast<SubModelKind>(k);
    if (kind == SubModelKind::wear && !wear) continue;
    for (const char *entry : runin::tribo::registered_sub_models(kind)[choice.of(kind)].citations)
      entries.push_back(entry);
  }
  if (wall) entries.push_back(kCiteGreenwoodWilliamson);
  return entries;
}

}    // namespace runin_lammps
