// Lin, Cheng & Tuan Table 1 model (engine/solid/table1.hpp; Lin, Cheng & Tuan, Table 1) on the paper's 8 x 10 x 20 hex8 mesh:
// 2079 nodes and 1600 elements, base reactions balance the 980 kN load exactly, spreading the load over a
// pyramid patch cuts the peak stress far below the point-load value, and the largest nodal base reaction
// is independent of how the load is spread (paper: 122.44 kN in every case).
#include <gtest/gtest.h>

#include "engine/solid/table1.hpp"

namespace dmi::solid {
namespace {

TEST(Table1, MeshEquilibriumAndDispersion) {
  Table1Setup setup;
  EXPECT_EQ(hex8_tapered_block(setup.block).n_nodes(), 2079);
  EXPECT_EQ(hex8_tapered_block(setup.block).n_elements(), 1600);
  setup.sloped = {SlopedFace::upstream};
  setup.measures = {Measure::von_mises};
  setup.locations = {Location::centroid};
  const std::vector<Table1Row> rows = table1_study(setup);
  ASSERT_EQ(rows.size(), 4u);
  for (const Table1Row& r : rows) {
    EXPECT_NEAR(r.total_reaction_kN(0), -980.0, 1e-8 * 980) << r.load.name;
    EXPECT_NEAR(r.total_reaction_kN.tail<2>().norm(), 0.0, 1e-8 * 980) << r.load.name;
    EXPECT_NEAR(r.max_node_reaction_kN, rows[0].max_node_reaction_kN, 1e-3 * rows[0].max_node_reaction_kN);
    EXPECT_GT(r.patch_scale, 0.9);
    EXPECT_LT(r.patch_scale, 1.1);
  }
  for (std::size_t c = 1; c < 4; ++c) EXPECT_LT(rows[c].peak_kPa[0][0], 0.5 * rows[0].peak_kPa[0][0]) << rows[c].load.name;
  // Same order as the paper's numbers (11 225 and 3 666 kPa, 122.44 kN).
  EXPECT_NEAR(rows[0].peak_kPa[0][0], kPaperBTable1PeakStress_kPa[0], 0.15 * kPaperBTable1PeakStress_kPa[0]);
  EXPECT_NEAR(rows[0].max_node_reaction_kN, kPaperBTable1FixedEndForce_kN, 0.1 * kPaperBTable1FixedEndForce_kN);
}

TEST(Table1, RejectsEmptySetup) {
  Table1Setup setup;
  setup.measures.clear();
  EXPECT_THROW(table1_study(setup), std::invalid_argument);
}

}  // namespace
}  // namespace dmi::solid
