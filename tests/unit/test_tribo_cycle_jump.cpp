// Cycle jumping: the jump's factor and its mean-depth tolerance.
#include "tribo/contact.h"
#include "tribo/cycle_jump.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

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

TEST(CycleJump, WithinChangeKeepsTheLargestSummitChangeAtTheTolerance)
{
  // a summit whose height changes by 2 nm per unit of the extra factor: 1e3 extra phases would move it 2 um
  const auto change = [](double e) { return 2e-9 * e; };
  const double extra = jump_extra_within_change(1e3, 16e-9, change);
  EXPECT_LE(change(extra), 16e-9);
  EXPECT_NEAR(extra, 8.0, 1e-12 * 1e3);
  // within the tolerance at the requested jump: the jump as requested
  EXPECT_EQ(jump_extra_within_change(5.0, 16e-9, change), 5.0);
  EXPECT_EQ(jump_extra_within_change(0.0, 16e-9, change), 0.0);
  // a change that is not linear in the factor (a summit dropping into its own widening flat)
  const auto sqrt_change = [](double e) { return 1e-9 * std::sqrt(e); };
  const double root = jump_extra_within_change(1e6, 10e-9, sqrt_change);
  EXPECT_LE(sqrt_change(root), 10e-9);
  EXPECT_NEAR(root, 100.0, 1e-12 * 1e6);
}

TEST(CycleJump, WithinChangeNamesABadTolerance)
{
  const auto change = [](double e) { return e; };
  for (double bad : {0.0, -1e-9, static_cast<double>(INFINITY), std::nan("")}) {
    try {
      jump_extra_within_change(1.0, bad, change);
      ADD_FAILURE() << "max_change " << bad << " accepted";
    } catch (const InvalidCoefficient &e) {
      EXPECT_NE(std::string(e.what()).find("max_change"), std::string::npos);
    }
  }
}
