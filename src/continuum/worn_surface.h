// How wear changes the asperity contact of a lubricated element (doc/lubricated_journal_bearing.md, "Worn
// summits"):
//   LawRq: Gaussian summits of the law's rq at the node's worn depth (the cell's surface as it wears);
//   TruncatedSummits: the unworn law's summits (rq at h = 0) cut at the top the node's worn volume sets
//     (tribo::GreenwoodTripp::top_after_wear): wear takes the highest summits first and no summit rises above
//     the cut, so the contact ends once the film is thicker than the cut.
#pragma once

namespace runin::continuum {

enum class WornSurface { LawRq, TruncatedSummits };

inline const char *to_string(WornSurface surface)
{
  return surface == WornSurface::TruncatedSummits ? "truncated" : "law_rq";
}

}    // namespace runin::continuum
