// The CalculiX cross-check's input and output (verify/calculix.hpp): the brick mesh is the cantilever's, the push adds
// up to the pulse's peak, and the sway is read back at every printed instant.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

#include "verify/calculix.hpp"

namespace dmi {
namespace {

struct Node {
  int id = 0;
  double x = 0, y = 0, z = 0;
};

// The section between "*KEY" and the next keyword line.
std::vector<std::string> block(const std::string& text, const std::string& key) {
  std::istringstream in(text);
  std::string line;
  std::vector<std::string> out;
  bool inside = false;
  while (std::getline(in, line)) {
    if (!line.empty() && line[0] == '*') inside = line.rfind(key, 0) == 0;
    else if (inside) out.push_back(line);
  }
  return out;
}

TEST(CalculixCantilever, MeshHoldsTheMemberTheBlockAndThePush) {
  const CantileverPulse p;
  const std::string inp = calculix_cantilever_input(p, 10, 2);
  // 11 columns of 2 bricks (10 along the member, 1 the block), each of two lines (16 entries, then 5).
  EXPECT_EQ(block(inp, "*ELEMENT, TYPE=C3D20R").size(), 2u * 11 * 2);
  EXPECT_EQ(block(inp, "*ELSET, ELSET=BLOCK").size(), 2u);
  double xmax = 0, ymin = 1, ymax = -1, zmax = 0;
  for (const std::string& l : block(inp, "*NODE, NSET=ALL")) {
    Node n;
    char c;
    std::istringstream(l) >> n.id >> c >> n.x >> c >> n.y >> c >> n.z;
    xmax = std::max(xmax, n.x), ymin = std::min(ymin, n.y), ymax = std::max(ymax, n.y), zmax = std::max(zmax, n.z);
  }
  EXPECT_DOUBLE_EQ(xmax, p.L + p.block_length);
  EXPECT_DOUBLE_EQ(ymax - ymin, p.d);
  EXPECT_DOUBLE_EQ(zmax, p.b);
  // One face of the block pressed: pressure x face area = the peak force.
  const std::vector<std::string> push = block(inp, "*DLOAD");
  ASSERT_EQ(push.size(), 1u);
  const double pressure = std::stod(push[0].substr(push[0].rfind(',') + 1));
  EXPECT_NEAR(pressure * p.block_length * p.b, p.peak_force, 1e-6 * p.peak_force);
  EXPECT_THROW(calculix_cantilever_input(p, 10, 3), std::invalid_argument);  // an odd count across the depth
}

TEST(CalculixCantilever, SwayIsReadAtEveryInstantTowardsThePush) {
  const std::string dat =
      "\n displacements (vx,vy,vz) for set END and time  0.4000000E-02\n\n"
      "       123  1.0E-05 -2.5E-03  0.0E+00\n"
      "\n displacements (vx,vy,vz) for set END and time  0.8000000E-02\n\n"
      "       123  2.0E-05 -7.5E-03  1.0E-20\n";
  const SwayHistory h = parse_calculix_sway(dat);
  ASSERT_EQ(h.t.size(), 2u);
  EXPECT_DOUBLE_EQ(h.t[1], 0.008);
  EXPECT_DOUBLE_EQ(h.sway[0], 2.5e-3);
  EXPECT_DOUBLE_EQ(h.peak(), 7.5e-3);
  EXPECT_THROW(parse_calculix_sway("no displacements here"), std::runtime_error);
}

// The residual sway is the centre of the ringing, whatever the phase at which the run ends.
TEST(CalculixCantilever, ResidualIsTheCentreOfTheRinging) {
  SwayHistory h;
  for (int k = 0; k <= 3000; ++k) h.t.push_back(k * 1e-3), h.sway.push_back(0.06 + 0.1 * std::sin(2 * 3.14159265358979 * k * 1e-3 / 0.9 + 0.3));
  EXPECT_NEAR(h.residual(0.83), 0.06, 1e-4);  // a window of 1.5 x 0.83 s spans a whole 0.9 s cycle
}

}  // namespace
}  // namespace dmi
