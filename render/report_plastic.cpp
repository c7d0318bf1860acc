// The report's rows on steel members that yield (design.json runs[].plastic; docs/design-checks.md "Plastic steel").
#include <algorithm>
#include <string>

#include "render/report_rows.hpp"

namespace dmi::render {

using nlohmann::json;

namespace {

const json* plastic(const RunData& r) {
  return r.design.contains("plastic") && r.design["plastic"].is_object() ? &r.design["plastic"] : nullptr;
}

std::string energy(const RunData& r, const char* key) {
  const json* p = plastic(r);
  if (!p || !(*p)["energy"].contains(key)) return "—";
  return fmt("%.4g kJ", (*p)["energy"][key].get<double>() / 1e3);
}

}  // namespace

json plastic_rows(const std::vector<RunData>& runs) {
  bool any = false;
  for (const auto& r : runs) any = any || plastic(r);
  if (!any) return json::array();
  std::vector<std::pair<std::string, std::function<std::string(const RunData&)>>> rows = {
      {"member model", [](const RunData& r) {
         const json* p = plastic(r);
         return p ? (*p)["member_model"].get<std::string>() + fmt(", f_y %.0f MPa", r.design.value("steel_yield_strength_Pa", 0.0) / 1e6)
                  : std::string("elastic");
       }},
      {"boulder's kinetic energy", [](const RunData& r) { return energy(r, "boulder_kinetic_J"); }},
      {"work of the impact on the members (largest)", [](const RunData& r) { return energy(r, "contact_work_max_J"); }},
      {"plastic work in the members", [](const RunData& r) { return energy(r, "plastic_work_J"); }},
      {"dissipated by the members' damping", [](const RunData& r) { return energy(r, "damping_J"); }}};
  std::vector<std::string> groups;
  for (const auto& r : runs)
    if (const json* p = plastic(r))
      for (auto it = (*p)["energy"]["by_group_J"].begin(); it != (*p)["energy"]["by_group_J"].end(); ++it)
        if (std::find(groups.begin(), groups.end(), it.key()) == groups.end()) groups.push_back(it.key());
  for (const std::string& g : groups)
    rows.push_back({"plastic work: " + g + "s", [g](const RunData& r) {
                      const json* p = plastic(r);
                      if (!p || !(*p)["energy"]["by_group_J"].contains(g)) return std::string("—");
                      return fmt("%.4g kJ", (*p)["energy"]["by_group_J"][g].get<double>() / 1e3);
                    }});
  rows.push_back({"largest strain (member)", [](const RunData& r) {
                    const json* p = plastic(r);
                    if (!p) return std::string("—");
                    double best = -1;
                    std::string who;
                    for (const auto& m : (*p)["members"])
                      if (m["peak_strain"].get<double>() > best) best = m["peak_strain"].get<double>(), who = m["member"].get<std::string>();
                    return fmt("%.3g %%", 100 * best) + " (" + who + ")";
                  }});
  rows.push_back({"residual drift of the crest", [](const RunData& r) {
                    const json* p = plastic(r);
                    if (!p || (*p)["residual_drift"].is_null()) return std::string("—");
                    const json& d = (*p)["residual_drift"];
                    return fmt("%.3g %%", 100 * d["drift"].get<double>()) + " (" + eng(d["residual_m"].get<double>(), "m") + ", still ringing ±" +
                           eng(d["amplitude_m"].get<double>(), "m") + (d["settled"].get<bool>() ? ")" : ": NOT SETTLED, run longer)");
                  }});
  rows.push_back({"dent of the struck pipe", [](const RunData& r) {
                    const json* p = plastic(r);
                    if (!p || (*p)["dent"].is_null()) return std::string("—");
                    const json& d = (*p)["dent"];
                    return eng(d["depth_m"].get<double>(), "m") + fmt(" (%.3g of D, ", d["depth_m"].get<double>() / d["diameter_m"].get<double>()) +
                           d["member"].get<std::string>() + ")";
                  }});
  return per_run_rows(runs, rows);
}

}  // namespace dmi::render
