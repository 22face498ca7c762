// The papers of the contact sub-models (BibTeX, for LAMMPS's log.cite): each class lists its own in `citations`
// (contact_model.h), so a host cites what the chosen models declare. Each entry's first line is what LAMMPS prints
// in its terse summary.
#pragma once

namespace runin::tribo {

inline constexpr const char *kCiteHertz =
    "RunIn normal model hertz: Hertz (1882)\n\n"
    "@Article{Hertz1882,\n author = {H. Hertz},\n title = {{\\\"U}ber die {B}er{\\\"u}hrung fester elastischer "
    "{K}{\\\"o}rper},\n journal = {Journal f{\\\"u}r die reine und angewandte Mathematik},\n year = 1882,\n"
    " volume = 92,\n pages = {156--171}\n}\n\n";
inline constexpr const char *kCiteJacksonGreen =
    "RunIn normal model elastic/plastic (loading): Jackson and Green (2005)\n\n"
    "@Article{JacksonGreen2005,\n author = {R. L. Jackson and I. Green},\n title = {A finite element study of "
    "elasto-plastic hemispherical contact against a rigid flat},\n journal = {Journal of Tribology},\n year = 2005,\n"
    " volume = 127,\n number = 2,\n pages = {343--354},\n doi = {10.1115/1.1866166}\n}\n\n";
inline constexpr const char *kCiteEtsionKligermanKadin =
    "RunIn normal model elastic/plastic (unloading): Etsion, Kligerman and Kadin (2005)\n\n"
    "@Article{EtsionKligermanKadin2005,\n author = {I. Etsion and Y. Kligerman and Y. Kadin},\n title = {Unloading "
    "of an elastic-plastic loaded spherical contact},\n journal = {International Journal of Solids and Structures},\n"
    " year = 2005,\n volume = 42,\n pages = {3716--3729}\n}\n\n";
inline constexpr const char *kCiteMindlin =
    "RunIn tangential model mindlin: Mindlin (1949)\n\n"
    "@Article{Mindlin1949,\n author = {R. D. Mindlin},\n title = {Compliance of elastic bodies in contact},\n"
    " journal = {Journal of Applied Mechanics},\n year = 1949,\n volume = 16,\n pages = {259--268}\n}\n\n";
inline constexpr const char *kCiteBrizmer =
    "RunIn friction model brizmer: Brizmer, Kligerman and Etsion (2007)\n\n"
    "@Article{BrizmerKligermanEtsion2007,\n author = {V. Brizmer and Y. Kligerman and I. Etsion},\n title = "
    "{Elastic-plastic spherical contact under combined normal and tangential loading in full stick},\n"
    " journal = {Tribology Letters},\n year = 2007,\n volume = 25,\n pages = {61--70}\n}\n\n";
inline constexpr const char *kCiteTabor =
    "RunIn friction model junction: Tabor (1959)\n\n"
    "@Article{Tabor1959,\n author = {D. Tabor},\n title = {Junction growth in metallic friction: the role of "
    "combined stresses and surface contamination},\n journal = {Proceedings of the Royal Society of London A},\n"
    " year = 1959,\n volume = 251,\n pages = {378--393}\n}\n\n";
inline constexpr const char *kCiteArchard =
    "RunIn wear model archard: Archard (1953)\n\n"
    "@Article{Archard1953,\n author = {J. F. Archard},\n title = {Contact and rubbing of flat surfaces},\n"
    " journal = {Journal of Applied Physics},\n year = 1953,\n volume = 24,\n pages = {981--988}\n}\n\n";
}    // namespace runin::tribo
