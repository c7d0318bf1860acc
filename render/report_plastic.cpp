// The report's rows on steel members that yield (design.json runs[].plastic; docs/design-checks.md "Plastic steel").
#include <algorithm>
#include <optional>
#include <string>

#include "design/plastic_record.hpp"
#include "render/report_rows.hpp"

namespace dmi::render {

using nlohmann::json;

namespace {

const std::optional<design::PlasticRecord>& plastic(const RunData& r) { return r.design.plastic; }

std::string kilojoules(const std::optional<double>& e) { return e ? fmt("%.4g kJ", *e / 1e3) : std::string("—"); }

}  // namespace

json plastic_rows(const std::vector<RunData>& runs) {
  std::vector<std::optional<design::PlasticRecord>> records;
  for (const auto& r : runs) records.push_back(plastic(r));
  if (std::none_of(records.begin(), records.end(), [](const auto& p) { return p.has_value(); })) return json::array();
  const auto of = [&runs, &records](const RunData& r) -> const std::optional<design::PlasticRecord>& { return records[&r - runs.data()]; };
  const auto energy = [of](double design::PlasticRecord::Energy::*e) {
    return [of, e](const RunData& r) { return of(r) ? kilojoules(of(r)->energy.*e) : std::string("—"); };
  };
  const auto maybe_energy = [of](std::optional<double> design::PlasticRecord::Energy::*e) {
    return [of, e](const RunData& r) { return of(r) ? kilojoules(of(r)->energy.*e) : std::string("—"); };
  };
  std::vector<std::pair<std::string, std::function<std::string(const RunData&)>>> rows = {
      {"member model", [of](const RunData& r) {
         return of(r) ? of(r)->member_model + fmt(", f_y %.0f MPa", r.design.steel_yield_strength_Pa / 1e6) : std::string("elastic");
       }},
      {"boulder's kinetic energy", maybe_energy(&design::PlasticRecord::Energy::boulder_kinetic_J)},
      {"work of the impact on the members (largest)", maybe_energy(&design::PlasticRecord::Energy::contact_work_max_J)},
      {"plastic work in the members", energy(&design::PlasticRecord::Energy::plastic_work_J)},
      {"dissipated by the members' damping", energy(&design::PlasticRecord::Energy::damping_J)}};
  std::vector<std::string> groups;
  for (const auto& p : records)
    if (p)
      for (const auto& [g, work] : p->energy.by_group_J)
        if (std::find(groups.begin(), groups.end(), g) == groups.end()) groups.push_back(g);
  for (const std::string& g : groups)
    rows.push_back({"plastic work: " + g + "s", [of, g](const RunData& r) {
                      if (!of(r) || !of(r)->energy.by_group_J.count(g)) return std::string("—");
                      return fmt("%.4g kJ", of(r)->energy.by_group_J.at(g) / 1e3);
                    }});
  rows.push_back({"largest strain (member)", [of](const RunData& r) {
                    if (!of(r)) return std::string("—");
                    double best = -1;
                    std::string who;
                    for (const auto& m : of(r)->members)
                      if (m.peak_strain > best) best = m.peak_strain, who = m.member;
                    return fmt("%.3g %%", 100 * best) + " (" + who + ")";
                  }});
  rows.push_back({"residual drift of the crest", [of](const RunData& r) {
                    if (!of(r) || !of(r)->residual_drift) return std::string("—");
                    const auto& d = *of(r)->residual_drift;
                    return fmt("%.3g %%", 100 * d.drift) + " (" + eng(d.residual_m, "m") + ", still ringing ±" + eng(d.amplitude_m, "m") +
                           (d.settled ? ")" : ": NOT SETTLED, run longer)");
                  }});
  rows.push_back({"dent of the struck pipe", [of](const RunData& r) {
                    if (!of(r) || !of(r)->dent) return std::string("—");
                    const auto& d = *of(r)->dent;
                    return eng(d.depth_m, "m") + fmt(" (%.3g of D, ", d.depth_m / d.diameter_m) + d.member + ")";
                  }});
  return per_run_rows(runs, rows);
}

}  // namespace dmi::render
