// The coefficient grammar's host adaptor for the unit tests (test_tribo_coefficient_grammar.cpp and the registry
// build's test_registry_coulomb_test.cpp): numbers by strtod, ERROR thrown as Failed (outside the grammar's kernel
// calls), WARNINGs kept, no material files.
#pragma once

#include "coefficient_grammar.h"

#include <cstdlib>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace runin_test {

struct Failed : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct CoefficientTestHost {
  std::vector<std::string> warnings;
  runin_coeff::Host host;
  explicit CoefficientTestHost(bool film)
  {
    host.style = "pair_coeff runin/asperity";
    host.film = film;
    host.fail = [](const std::string &message) { throw Failed(message); };
    host.warning = [this](const std::string &message) { warnings.push_back(message); };
    host.is_number = [](const char *text) {
      char *end = nullptr;
      std::strtod(text, &end);
      return *text && *end == '\0';
    };
    host.material = [](const char *, const char *, const char *) -> runin::tribo::ContactParameters {
      throw Failed("no material files here");
    };
  }
  // host.warning holds `this`
  CoefficientTestHost(const CoefficientTestHost &) = delete;
  CoefficientTestHost &operator=(const CoefficientTestHost &) = delete;
};

// A deck line as words (arg[0..narg)).
struct Words {
  std::vector<std::string> words;
  std::vector<char *> arg;
  explicit Words(const std::string &line)
  {
    std::istringstream in(line);
    for (std::string w; in >> w;) words.push_back(w);
    for (auto &w : words) arg.push_back(w.data());
  }
  int narg() const { return static_cast<int>(arg.size()); }
};

// The model choice with the normal and friction laws named (the other kinds at their defaults).
inline runin::tribo::ContactModelChoice choice_of(const char *normal, const char *friction)
{
  using runin::tribo::SubModelKind;
  runin::tribo::ContactModelChoice choice;
  choice.index[static_cast<int>(SubModelKind::normal)] = runin::tribo::find_sub_model(SubModelKind::normal, normal);
  choice.index[static_cast<int>(SubModelKind::friction)] = runin::tribo::find_sub_model(SubModelKind::friction, friction);
  return choice;
}

}    // namespace runin_test
