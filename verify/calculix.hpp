// The independent code of the plastic member cross-check: the cantilever of verify/plastic_models.hpp meshed in
// CalculiX's 20-node bricks with reduced integration (C3D20R; an even number of them across the depth, so that a fully
// plastic section's stress block is integrated exactly), *PLASTIC with kinematic hardening, NLGEOM, *DYNAMIC with
// alpha = 0 (the average-acceleration rule); the push a pressure on the block's face; the sway of the cantilever's end
// read back. (CalculiX's own beam elements expand into one brick across the depth, whose two integration points
// overstate a rectangle's plastic moment by 2 / sqrt(3) - 1 = 15.5 %: not a reference for a plastic hinge.)
#pragma once
#include <string>

#include "verify/plastic_models.hpp"

namespace dmi {

// The input file: `along` bricks along the cantilever, `across` (even) across its depth, one across its width and
// the block's length.
std::string calculix_cantilever_input(const CantileverPulse& p, int along, int across);
// Runs ccx on it in a fresh folder under `work_dir`; throws std::runtime_error when ccx is missing or fails.
SwayHistory calculix_cantilever_sway(const CantileverPulse& p, int along, int across, const std::string& work_dir);
// ccx's .dat text: the y displacement printed at every output instant for the one node of the set END, negated (the
// push is towards -y).
SwayHistory parse_calculix_sway(const std::string& dat_text);

}  // namespace dmi
