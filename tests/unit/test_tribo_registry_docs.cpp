// The registered sub-models and the table of them in doc/pair_runin_asperity.rst are the same list: a law added to the
// registry without its row (kind, name, coefficients in order), or a row left for a law that is gone, fails here.
#include "tribo/contact_model.h"

#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace tribo = runin::tribo;

namespace {

// "kind|name|coefficients" of each row of the doc's list-table whose first cell is a kind.
std::set<std::string> documented_rows()
{
  std::ifstream in(std::string(RUNIN_SOURCE_DIR) + "/doc/pair_runin_asperity.rst");
  std::vector<std::string> cells;
  std::set<std::string> rows;
  auto flush = [&] {
    if (cells.size() >= 4 && cells[2].size() > 2 && cells[2].front() == '*' && cells[2].back() == '*')
      rows.insert(cells[0] + "|" + cells[2].substr(1, cells[2].size() - 2) + "|" + cells[3]);
    cells.clear();
  };
  for (std::string line; std::getline(in, line);) {
    const auto at = line.find_first_not_of(' ');
    if (at == std::string::npos) continue;
    if (line.compare(at, 4, "* - ") == 0) {
      flush();
      cells.push_back(line.substr(at + 4));
    } else if (line.compare(at, 2, "- ") == 0 && !cells.empty()) {
      cells.push_back(line.substr(at + 2));
    } else {
      flush();
    }
  }
  flush();
  return rows;
}

std::set<std::string> registered_rows()
{
  std::set<std::string> rows;
  for (int k = 0; k < tribo::kSubModelKinds; ++k) {
    const auto kind = static_cast<tribo::SubModelKind>(k);
    for (const auto &info : tribo::registered_sub_models(kind)) {
      std::string names;
      for (const char *n : info.coefficient_names) names += (names.empty() ? "" : " ") + std::string(n);
      rows.insert(std::string(tribo::sub_model_kind_name(kind)) + "|" + info.name + "|" + names);
    }
  }
  return rows;
}

}    // namespace

TEST(RegistryDocs, EveryRegisteredSubModelHasItsTableRowAndNoOther)
{
  const auto documented = documented_rows(), registered = registered_rows();
  ASSERT_FALSE(documented.empty()) << "no sub-model table found in doc/pair_runin_asperity.rst";
  for (const auto &row : registered) EXPECT_TRUE(documented.count(row)) << "not in the doc's table: " << row;
  for (const auto &row : documented) EXPECT_TRUE(registered.count(row)) << "in the doc's table, not registered: " << row;
}
