#include "surfaces/common/grid_rows.h"

#include <gtest/gtest.h>

#include "framework/core/error.h"

namespace fitfeel {
namespace {

SurfaceGrid Rows(std::initializer_list<double> centres) {
  SurfaceGrid grid;
  grid.rows = static_cast<int>(centres.size());
  grid.columns = 1;
  grid.row_position.resize(grid.rows);
  int i = 0;
  for (double c : centres) grid.row_position[i++] = c;
  return grid;
}

TEST(RowEdgesTest, HalfwayBetweenCentresFromTheFirstEdge) {
  PartSpec part;
  part.name = "shaft";
  const std::vector<double> edges = RowEdges(part, Rows({1.0, 3.0, 5.0}));
  EXPECT_EQ(edges, (std::vector<double>{0.0, 2.0, 4.0, 6.0}));
}

TEST(RowEdgesTest, RefusesRowsOutOfOrderAndAOneRowGridWithoutLength) {
  PartSpec part;
  part.name = "shaft";
  EXPECT_THROW(RowEdges(part, Rows({1.0, 1.0})), UserError);
  EXPECT_THROW(RowEdges(part, Rows({2.0, 1.0})), UserError);
  EXPECT_THROW(RowEdges(part, Rows({1.0})), UserError);  // no geometry: no length
  SurfaceGrid mismatched = Rows({1.0, 2.0});
  mismatched.rows = 3;
  EXPECT_THROW(RowEdges(part, mismatched), UserError);
}

}  // namespace
}  // namespace fitfeel
