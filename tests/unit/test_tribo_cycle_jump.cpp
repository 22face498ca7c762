// Cycle jumping: the jump's factor and its mean-depth tolerance.
#include "tribo/contact.h"
#include "tribo/cycle_jump.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace runin::tribo;

TEST(CycleJump, JumpExtraKeepsAJumpWithinTheDepthTolerance)
{
  // 0.01 nm per phase, 99 extra phases: 0.99 nm <= 1 nm
  EXPECT_EQ(jump_extra(99.0, 0.01e-9, 1e-9), 99.0);
  EXPECT_EQ(jump_extra(0.0, 0.01e-9, 1e-9), 0.0);
  // no wear in the phase (no contact): it is not repeated, or the sliding it stands for would grow by M phases
  // of nothing (s up by 1e7 m in one jump at 0.2 MPa before this was found)
  EXPECT_EQ(jump_extra(1e6, 0.0, 1e-9), 0.0);
}

TEST(CycleJump, JumpExtraReducesAJumpToTheDepthTolerance)
{
  const double extra = jump_extra(1e5, 2e-15, 0.1e-9);
  EXPECT_LT(extra, 1e5);
  EXPECT_NEAR(extra * 2e-15, 0.1e-9, 1e-12 * 0.1e-9);
}

TEST(CycleJump, BadArgumentsNameThemselves)
{
  const auto message = [](double requested, double phase, double max_depth) {
    try {
      jump_extra(requested, phase, max_depth);
    } catch (const InvalidCoefficient &e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_NE(message(-1.0, 1e-12, 1e-9).find("M:"), std::string::npos);
  EXPECT_NE(message(INFINITY, 1e-12, 1e-9).find("M:"), std::string::npos);
  EXPECT_NE(message(1.0, 1e-12, 0.0).find("max_depth"), std::string::npos);
  EXPECT_NE(message(1.0, 1e-12, std::nan("")).find("max_depth"), std::string::npos);
  EXPECT_NE(message(1.0, std::nan(""), 1e-9).find("phase"), std::string::npos);
}
