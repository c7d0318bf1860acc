// The Pareto charts of `bench --out`: error against run time per variant group of the MPM studies (bar, disks, dam),
// and Lin & Yang's verification 1 by frame integrator, the front joined.
#pragma once
#include <string>

#include <nlohmann/json.hpp>

namespace dmi::render {

// `bench` is the JSON `damimpact bench --json` prints; the charts go to out/pareto_<case>.png.
void write_bench_charts(const nlohmann::json& bench, const std::string& out);

}  // namespace dmi::render
