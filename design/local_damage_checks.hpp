// Local damage of the struck concrete face (docs/design-checks.md, "Local damage"): the boulder of the design basis
// (mass, diameter, speed at impact) as a hard projectile on a bare concrete face, by the empirical formulae of
// missile-impact practice (design/local_damage), against the dam's thickness at the impact height. Perforation is an
// ultimate-level check, scabbing of the downstream face a serviceability-level one.
#pragma once
#include <optional>
#include <vector>

#include "core/design_basis.hpp"
#include "design/checks.hpp"
#include "design/limits.hpp"
#include "design/section_records.hpp"

namespace dmi::design {

// The thickness of a concrete gravity dam's section at height y (m), linear between base and crest.
double section_thickness_at(const DamBasis& d, double y);

// The local damage record and its two checks; none (and no checks) unless a boulder strikes the bare
// face of a concrete gravity dam whose section the basis records.
std::optional<LocalDamageRecord> local_damage_checks(const DesignBasis& b, const ConcreteLimits& L, std::vector<Check>& checks);

}  // namespace dmi::design
