#include "framework/tradeoff/grid_ladder.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "framework/core/error.h"

namespace fitfeel::tradeoff {
namespace {

using ::testing::HasSubstr;

std::string Message(const std::string& text) {
  try {
    ParseLadder(text);
  } catch (const UserError& e) {
    return e.what();
  }
  return "";
}

TEST(GridLadder, ParsesGridsAndAuto) {
  const std::vector<Resolution> ladder = ParseLadder("8x36, 20X90,auto");
  ASSERT_EQ(ladder.size(), 3u);
  EXPECT_EQ(ladder[0].rows, 8);
  EXPECT_EQ(ladder[0].columns, 36);
  EXPECT_EQ(ladder[1].rows, 20);
  EXPECT_EQ(ladder[1].columns, 90);
  EXPECT_TRUE(ladder[2].is_auto());
  EXPECT_EQ(Label(ladder[0]), "8x36");
  EXPECT_EQ(Label(ladder[2]), "auto");
}

TEST(GridLadder, RejectsMalformedItemsWithTheItem) {
  EXPECT_THAT(Message("8x36,,20x90"), HasSubstr("empty item"));
  EXPECT_THAT(Message("40"), HasSubstr("'40'"));
  EXPECT_THAT(Message("0x36"), HasSubstr("positive integers"));
  EXPECT_THAT(Message("8x-36"), HasSubstr("'8x-36'"));
  EXPECT_THAT(Message("8x36x2"), HasSubstr("'8x36x2'"));
  EXPECT_THAT(Message("8x35"), HasSubstr("even"));
  EXPECT_THAT(Message("4000x36000"), HasSubstr("cells per part"));
  EXPECT_THAT(Message("8x36,8x36"), HasSubstr("twice"));
  EXPECT_THAT(Message("auto,auto"), HasSubstr("twice"));
  EXPECT_THAT(Message(""), HasSubstr("empty item"));
}

TEST(GridLadder, DefaultLadderRefinesMonotonically) {
  const std::vector<Resolution> ladder = DefaultLadder();
  ASSERT_GE(ladder.size(), 2u);
  for (std::size_t k = 1; k < ladder.size(); ++k) {
    EXPECT_GE(ladder[k].rows, ladder[k - 1].rows);
    EXPECT_GE(ladder[k].columns, ladder[k - 1].columns);
    EXPECT_GT(ladder[k].rows * ladder[k].columns, ladder[k - 1].rows * ladder[k - 1].columns);
    EXPECT_EQ(ladder[k].columns % 2, 0);
  }
}

}  // namespace
}  // namespace fitfeel::tradeoff
