// Lin, Cheng & Tuan, Table 1 study: prints the markdown tables of engine/solid/table1.hpp for the
// upstream-, downstream- and symmetrically sloped column.   build/bench/paper_b_table1
#include <cstdio>

#include "engine/solid/table1.hpp"

int main() {
  dmi::solid::Table1Setup setup;
  setup.sloped = {dmi::solid::SlopedFace::upstream, dmi::solid::SlopedFace::downstream, dmi::solid::SlopedFace::both};
  const auto rows = dmi::solid::table1_study(setup);
  std::fputs(dmi::solid::format_table1(setup, rows).c_str(), stdout);
  return 0;
}
