// The ultimate level of steel members that yield (docs/design-checks.md, "Plastic steel"): from results.h5's
// frame/plastic (per element: plastic work, peak strain at the section surface, accumulated plastic strain),
// frame/displacement, the energies and the member envelopes. Checks: the peak strain against a limiting strain
// (EN 1993-1-5 Annex C.8), the section class of a yielded pipe (class 1 where hinges form, EN 1993-1-1 5.6(2)), the
// flexural buckling of compressed members (EN 1993-1-1 6.3.1), the residual drift of the crest (FEMA P-58-1 Table C-1)
// and the dent of the struck pipe (DNV-RP-C204 sec. 3.10); besides, the energy the members absorbed by member group.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/design_basis.hpp"
#include "design/checks.hpp"
#include "design/limits.hpp"
#include "design/loads.hpp"
#include "design/members.hpp"
#include "design/plastic_record.hpp"
#include "engine/io/results.hpp"

namespace dmi::design {

// design.json's "plastic" (null when no member is elasto-plastic): the energy split, per member and per member group
// (the name up to its first '_': column, beam, brace, tie), the residual drift and the dent; the checks are appended.
std::optional<PlasticRecord> plastic_part(const Results& r, const FrameInfo& f, const std::vector<MemberEnvelope>& members,
                                          const std::optional<DesignBasis>& basis, const Contact& contact, const SteelLimits& S,
                                          std::vector<Check>& checks, const std::string& where);

// The member group of a member name: its part before the first '_' (the whole name without one).
std::string member_group(const std::string& name);

// Residual displacement of a history u(t) that ends oscillating about its permanent set: the mean of u over the last
// `window` seconds minus u at the first sample, and the half range left in that window (the amplitude still ringing).
struct Residual {
  double value = 0, amplitude = 0;
};
Residual residual_of(const std::vector<double>& time, const std::vector<double>& u, double window);

}  // namespace dmi::design
