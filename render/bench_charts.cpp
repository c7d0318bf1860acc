#include "render/bench_charts.hpp"

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <utility>
#include <vector>

#include "render/charts.hpp"

namespace dmi::render {

void write_bench_charts(const nlohmann::json& bench, const std::string& out) {
  const nlohmann::json& j = bench;
  for (const char* cs : {"bar", "disks", "dam"}) {  // Pareto charts of the MPM studies: one point set per variant group
    if (!j.contains(cs)) continue;
    ChartSpec c;
    c.title = std::string(cs) + ": error against run time";
    c.log_x = c.log_y = true;
    c.x_label = "wall time [s]";
    c.y_label = std::string(cs) == "bar" ? "period error [-]" : std::string(cs) == "disks" ? "|E(3 s) / E0 - 1| [-]" : "base shear error vs Richardson [-]";
    std::vector<std::string> groups;
    for (const auto& p : j[cs]["points"])
      if (std::find(groups.begin(), groups.end(), p["group"].get<std::string>()) == groups.end()) groups.push_back(p["group"]);
    static const std::array<unsigned char, 3> pal[] = {{31, 119, 180}, {255, 127, 14}, {44, 160, 44}, {214, 39, 40}, {148, 103, 189}, {140, 86, 75}, {227, 119, 194}, {127, 127, 127}};
    for (std::size_t g = 0; g < groups.size(); ++g) {
      Curve pts;
      pts.label = groups[g], pts.points = true, pts.color = pal[g % 8];
      for (const auto& p : j[cs]["points"])
        if (p["group"] == groups[g] && !p.contains("failed") && p.contains("error") && p["error"].is_number())
          pts.x.push_back(p["wall_seconds"]), pts.y.push_back(p["error"]);
      if (pts.x.size() >= 2) c.curves.push_back(pts);  // a group whose error is unknown (not converged) has no curve
    }
    std::vector<std::pair<double, double>> front;
    for (const auto& p : j[cs]["points"])
      if (p["front"].get<bool>()) front.push_back({p["wall_seconds"], p["error"]});
    std::sort(front.begin(), front.end());
    Curve f;
    f.label = "Pareto front", f.color = {60, 60, 60};
    for (const auto& [x, y] : front) f.x.push_back(x), f.y.push_back(y);
    if (f.x.size() >= 2) c.curves.push_back(f);
    if (c.curves.empty()) {
      std::fprintf(stderr, "bench: no chart for %s: fewer than two points with a known error\n", cs);
      continue;
    }
    render_chart(c, (std::filesystem::path(out) / ("pareto_" + std::string(cs) + ".png")).string());
  }
  if (j.contains("a5")) {
    ChartSpec c;
    c.title = "Lin & Yang verification 1: error against run time";
    c.log_x = true;
    c.x_label = "wall time [s]", c.y_label = "NRMS error vs converged FE [-]";
    for (const char* integ : {"explicit", "newmark"}) {
      Curve pts;
      pts.label = std::string(integ) + " frame";
      pts.points = true;
      pts.color = std::string(integ) == "explicit" ? std::array<unsigned char, 3>{31, 119, 180} : std::array<unsigned char, 3>{255, 127, 14};
      for (const auto& p : j["a5"]["points"])
        if (p["integrator"] == integ) pts.x.push_back(p["wall_seconds"]), pts.y.push_back(p["error"]);
      c.curves.push_back(pts);
    }
    std::vector<std::pair<double, double>> front;
    for (const auto& p : j["a5"]["points"])
      if (p["front"].get<bool>()) front.push_back({p["wall_seconds"], p["error"]});
    std::sort(front.begin(), front.end());
    Curve f;
    f.label = "Pareto front";
    f.color = {60, 60, 60};
    for (const auto& [x, y] : front) f.x.push_back(x), f.y.push_back(y);
    c.curves.push_back(f);
    render_chart(c, (std::filesystem::path(out) / "pareto_a5.png").string());
  }
}

}  // namespace dmi::render
