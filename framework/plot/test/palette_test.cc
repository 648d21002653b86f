#include "framework/plot/palette.h"

#include <gtest/gtest.h>

namespace fitfeel::plot {
namespace {

// "Readable in grey": the colour map's lightness must rise strictly from one end to the other, so
// that a grey rendering still orders the values.
TEST(Palette, ViridisLuminanceRisesMonotonically) {
  for (std::size_t k = 1; k < kViridis.size(); ++k) {
    EXPECT_GT(RelativeLuminance(kViridis[k]), RelativeLuminance(kViridis[k - 1])) << "anchor " << k;
  }
  EXPECT_LT(RelativeLuminance(kViridis.front()), 0.05);
  EXPECT_GT(RelativeLuminance(kViridis.back()), 0.7);
}

TEST(Palette, LuminanceOfReferenceColours) {
  EXPECT_DOUBLE_EQ(RelativeLuminance(0x000000), 0.0);
  EXPECT_NEAR(RelativeLuminance(0xffffff), 1.0, 1e-12);
  EXPECT_NEAR(RelativeLuminance(0x808080), 0.2159, 1e-4);  // sRGB mid grey
}

}  // namespace
}  // namespace fitfeel::plot
