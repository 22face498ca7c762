// LAMMPS fix ave/time (mode scalar) reader: column selection by name and one-line errors.
#include <gtest/gtest.h>

#include <sstream>

#include "coupling/ave_time_reader.h"

using runin::coupling::InputFormatError;
using runin::coupling::parse_ave_time;

namespace {
const char *kGood =
    "# Time-averaged data for fix fric_out\n"
    "# TimeStep v_slide c_fric[1] c_fric[2] c_fric[3] c_fric[4] c_fric[5]\n"
    "100 1.0e-07 2.1e-3 1.5e-3 0.71 40 1.2e-22\n"
    "\n"
    "200 2.0e-07 2.0e-3 1.5e-3 0.69 41 1.3e-22\n";

std::string error_of(const std::string &text) {
  std::istringstream in(text);
  try {
    parse_ave_time(in, "fric.txt");
  } catch (const InputFormatError &e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST(CouplingAveTime, SelectsColumnsByHeaderName) {
  std::istringstream in(kGood);
  const auto table = parse_ave_time(in, "fric.txt");
  ASSERT_EQ(table.rows(), 2u);
  EXPECT_EQ(table.column_names().size(), 7u);
  EXPECT_EQ(table.column("v_slide"), (std::vector<double>{1.0e-07, 2.0e-07}));
  EXPECT_EQ(table.column("c_fric[3]"), (std::vector<double>{0.71, 0.69}));
  EXPECT_EQ(table.column("TimeStep"), (std::vector<double>{100, 200}));
}

TEST(CouplingAveTime, MalformedInputNamesFileLineAndProblem) {
  const std::string header = "# TimeStep v_slide c_fric[3]\n";
  const std::string short_row = error_of(header + "100 1e-7 0.7\n200 2e-7\n");
  EXPECT_NE(short_row.find("fric.txt:3: expected 3 values"), std::string::npos) << short_row;
  const std::string not_number = error_of(header + "100 1e-7 0.7x\n");
  EXPECT_NE(not_number.find("fric.txt:2: column 'c_fric[3]': '0.7x' is not a number"), std::string::npos)
      << not_number;
  EXPECT_NE(error_of("100 1e-7 0.7\n").find("fric.txt:1: data before"), std::string::npos);
  EXPECT_NE(error_of("# TimeStep Number-of-rows\n100 5\n").find("mode vector"), std::string::npos);
  EXPECT_NE(error_of(header + "100 1e-7 nan\n").find("non-finite"), std::string::npos);
  EXPECT_NE(error_of(header).find("no data rows"), std::string::npos);
  for (const auto &message : {short_row, not_number}) EXPECT_EQ(message.find('\n'), std::string::npos);

  std::istringstream in(kGood);
  const auto table = parse_ave_time(in, "fric.txt");
  try {
    table.column("v_slid");
    FAIL() << "unknown column accepted";
  } catch (const InputFormatError &e) {
    EXPECT_NE(std::string(e.what()).find("no column 'v_slid'"), std::string::npos);
  }
}

TEST(CouplingAveTime, MissingFileIsReported) {
  EXPECT_THROW(runin::coupling::read_ave_time("/nonexistent/fric.txt"), InputFormatError);
}
