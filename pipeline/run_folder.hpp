// A run's output folder as the pipeline reads it: nothing yet, an interrupted run (its checkpoint), or a complete one
// (results.h5 without a partial file) -- and whether a complete one was computed for a given scenario. The one rule
// by which `run --restart`, a grid study's levels and a sweep's cases resume or keep what a folder holds.
#pragma once
#include <filesystem>
#include <string>

#include "engine/scenario/config.hpp"

namespace dmi::pipeline {

enum class RunState { absent, interrupted, complete };

RunState run_state(const std::filesystem::path& dir);

// The folder holds a complete, readable run of the scenario (engine/scenario/identity.hpp: the same low-level scenario
// and variant).
bool holds_run_of(const std::filesystem::path& dir, const Scenario& s);

}  // namespace dmi::pipeline
