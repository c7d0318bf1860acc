// The whole chain of `damimpact run`: simulation, design checks, pictures and report -- for one cell size, or as a
// grid study at three (design/grid_study.hpp).
#pragma once
#include <string>

#include "pipeline/simulate.hpp"

namespace dmi::pipeline {

struct ChainRequest {
  SimulateRequest simulate;
  std::string limits_file;  // "" : default limits
  bool report = true;       // pictures and the HTML + PDF report
  bool grid_study = false;
  double grid_ratio = 1.4142135623730951;
  std::string quantity = "von_mises";  // the particles' colouring in pictures
};

// Returns the design verdict: 0 every check passes, 1 a check fails.
int run_chain(const ChainRequest& r);

}  // namespace dmi::pipeline
