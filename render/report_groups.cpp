// The report's summary of a run's member checks by member group (docs/guide.md, "Reading the report"): a frame of many
// members (a steel open dam's columns, beams, braces and ties) gives a check per member; the summary shows, per check and
// group, how many members it covers and fail and which member governs.
#include <algorithm>
#include <map>
#include <string>
#include <utility>

#include "design/plastic_checks.hpp"
#include "design/verdict.hpp"
#include "render/report_rows.hpp"

namespace dmi::render {

using nlohmann::json;

json check_group_rows(const design::RunDesign& design_run) {
  struct Group {
    std::string title, member, unit, level;
    int members = 0, failed = 0;
    double util = -1;
    double demand = 0, capacity = 0;
  };
  std::map<std::pair<std::string, std::string>, Group> groups;  // (check id, group)
  std::vector<std::pair<std::string, std::string>> order;
  for (const design::Check& c : design_run.checks) {
    const std::string& member = c.member;
    if (member.empty() || member.rfind("solid: ", 0) == 0 || c.level == "information") continue;
    const auto key = std::make_pair(c.id, design::member_group(member));  // column_0_1 -> column
    auto [it, fresh] = groups.try_emplace(key);
    if (fresh) order.push_back(key);
    Group& g = it->second;
    g.title = c.title, g.unit = c.unit;
    if (g.level.empty() || g.level == c.level) g.level = c.level;
    else g.level = "both";
    ++g.members;
    g.failed += c.passed ? 0 : 1;
    if (c.utilisation > g.util) g.util = c.utilisation, g.member = member, g.demand = c.demand, g.capacity = c.capacity;
  }
  if (std::none_of(groups.begin(), groups.end(), [](const auto& g) { return g.second.members > 1; })) return json::array();
  json rows = json::array();
  for (const auto& key : order) {
    const Group& g = groups.at(key);
    const std::string level = g.level == "ultimate" ? "ULS" : g.level == "serviceability" ? "SLS" : "SLS, ULS";
    rows.push_back({{"title", g.title}, {"level", level}, {"group", key.second + "s"}, {"members", g.members}, {"failed", g.failed}, {"member", g.member},
                    {"demand", eng(g.demand, g.unit)}, {"capacity", eng(g.capacity, g.unit)}, {"util", fmt("%.2f", g.util)},
                    {"status_class", g.failed > 0 ? "fail" : "pass"}});
  }
  return rows;
}

}  // namespace dmi::render
