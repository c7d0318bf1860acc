// The report's rows on the pressure of the struck face (design.json runs[].face_profile) and the pressure sensors
// (runs[].sensors); docs/results.md "Pressures".
#include <algorithm>
#include <cstdio>
#include <string>

#include "render/charts.hpp"
#include "design/grid_study_record.hpp"
#include "design/phases.hpp"
#include "design/pressures.hpp"
#include "render/report_rows.hpp"

namespace dmi::render {

using nlohmann::json;

namespace {

const std::optional<design::FaceProfileAtMoment>& face(const RunData& r) { return r.design.face_profile; }

const std::vector<design::SensorPeak>& sensors_of(const RunData& r) { return r.design.sensors; }

using Face = design::FaceProfileAtMoment;

}  // namespace

json pressure_rows(const std::vector<RunData>& runs) {
  // Each run's records, read once; a row looks its run's up.
  std::vector<std::optional<Face>> faces;
  std::vector<std::vector<design::SensorPeak>> peaks;
  for (const auto& r : runs) faces.push_back(face(r)), peaks.push_back(sensors_of(r));
  const auto index = [&runs](const RunData& r) { return static_cast<std::size_t>(&r - runs.data()); };
  // The row of a face quantity: its value per run, "—" where the run has no face profile.
  const auto face_row = [&faces, index](const std::string& key, std::function<std::string(const Face&)> f) {
    return std::pair<std::string, std::function<std::string(const RunData&)>>{
        key, [&faces, index, f](const RunData& r) { return faces[index(r)] ? f(*faces[index(r)]) : std::string("—"); }};
  };
  std::vector<std::pair<std::string, std::function<std::string(const RunData&)>>> rows;
  if (std::any_of(faces.begin(), faces.end(), [](const std::optional<Face>& f) { return f.has_value(); })) {
    rows.push_back(face_row("instant of the largest moment about the foot", [](const Face& f) { return eng(f.time_s, "s"); }));
    rows.push_back(face_row("resultant of the face pressure", [](const Face& f) { return eng(f.resultant_N, "N"); }));
    rows.push_back(face_row("its height above the foot", [](const Face& f) { return fmt("%.3g m", f.height_m); }));
    rows.push_back(face_row("its moment about the foot", [](const Face& f) { return eng(f.moment_N_m, "N m"); }));
    rows.push_back(face_row("largest pressure of the profile (element length × face width)", [](const Face& f) {
      std::size_t k = 0;
      for (std::size_t b = 0; b < f.pressure_Pa.size(); ++b)
        if (f.pressure_Pa[b] > f.pressure_Pa[k]) k = b;
      return eng(f.pressure_Pa[k], "Pa") + fmt(" at %.3g m", f.positions_m[k]);
    }));
    rows.push_back(face_row("largest resultant over the run", [](const Face& f) { return eng(f.peak_resultant_N, "N") + " at " + eng(f.peak_resultant_time_s, "s"); }));
  }
  std::vector<std::string> sensors;
  for (const auto& list : peaks)
    for (const design::SensorPeak& s : list)
      if (std::find(sensors.begin(), sensors.end(), s.name) == sensors.end()) sensors.push_back(s.name);
  for (const std::string& name : sensors)
    rows.push_back({"sensor " + name + ": peak pressure", [&peaks, index, name](const RunData& r) {
                      for (const design::SensorPeak& s : peaks[index(r)])
                        if (s.name == name) return eng(s.peak_pressure_Pa, "Pa") + " at " + eng(s.peak_time_s, "s");
                      return std::string("—");
                    }});
  return rows.empty() ? json::array() : per_run_rows(runs, rows);
}

}  // namespace dmi::render

namespace dmi::render {

namespace {

// "± n %" of a grid-study quantity of the run, or "".
std::string gci_of(const design::DesignDocument& design_doc, const std::string& variant, const std::string& id) {
  if (const auto& gs = design_doc.grid_study)
    for (const design::GridQuantity& q : gs->quantities)
      if (q.id == id && q.variant == variant) return fmt(", grid ± %.0f %%", 100 * q.gci);
  return "";
}

}  // namespace

json debris_practice_rows(const std::vector<RunData>& runs, const design::DesignDocument& design_doc) {
  json rows = json::array();
  for (const auto& r : runs) {
    const std::optional<design::DebrisLoad>& p = r.design.debris_phases;
    if (!p) continue;
    const std::string run = r.variant.empty() ? "simulation" : r.variant;
    const double peak = p->phases.peak_N;
    auto row = [&](const std::string& model, const std::string& source, double value, const std::string& sim, double simulated, const std::string& note) {
      rows.push_back({{"run", run}, {"model", model}, {"source", source}, {"value", eng(value, "N")}, {"simulated", sim},
                      {"ratio", simulated > 0 ? fmt("%.2f", value / simulated) : std::string("—")}, {"note", note}});
    };
    const std::string peak_text = eng(peak, "N") + " (peak" + gci_of(design_doc, r.variant, "debris_peak") + ")";
    row("α = 2.5, ρ v² h w", p->geo.source, p->geo.force_N, peak_text, peak, "");
    row(fmt("α = 5.3 Fr^-1.5 = %.2f", p->cui.alpha) + fmt(" (Fr %.2f)", p->froude), p->cui.source, p->cui.force_N, peak_text, peak,
        p->cui_in_range ? "second-hand formula" : "second-hand formula, outside its data range (Fr about 2.3-6.2)");
    if (p->deposit && p->phases.static_N)
      row(fmt("deposit at rest, h_d = %.2f m: ρ g h_d² w / 2", p->deposit->height_m), "hydrostatic (K = 1), the upper bound of a granular deposit",
          p->deposit->hydrostatic_N, eng(*p->phases.static_N, "N") + " (static tail" + gci_of(design_doc, r.variant, "debris_static") + ")",
          *p->phases.static_N, "h_d: the face profile's loaded height over the last 10 % of the run");
  }
  return rows;
}

}  // namespace dmi::render

namespace dmi::render {

// The contact pressure along each run's struck face (design.json runs[].face_profile) at the instant of its largest
// moment about the face's foot: a step curve per run, pressure across, position along the face up.
ChartSpec face_profile_chart(const std::vector<RunData>& runs) {
  ChartSpec c;
  c.title = "contact pressure on the struck face, at its largest moment about the foot";
  c.x_label = "pressure [kPa]", c.y_label = "position along the face from its foot [m]";
  c.x_tight = false;
  for (std::size_t i = 0; i < runs.size(); ++i) {
    const std::optional<Face> f = face(runs[i]);
    if (!f) continue;
    Curve cv;
    char b[200];
    const double R = f->resultant_N;
    std::snprintf(b, sizeof b, "%st = %.2f ms, resultant %.3g %s at %.2f m", runs[i].variant.empty() ? "" : (nice_variant(runs[i].variant) + ", ").c_str(),
                  f->time_s * 1e3, R >= 1e6 ? R * 1e-6 : R * 1e-3, R >= 1e6 ? "MN" : "kN", f->height_m);
    cv.label = b;
    cv.color = colour(i);
    cv.dashed = runs[i].variant == "without_buffer";
    for (std::size_t k = 0; k < f->pressure_Pa.size(); ++k) {
      const double p = f->pressure_Pa[k] * 1e-3, mid = f->positions_m[k], half = 0.5 * f->lengths_m[k];
      cv.x.insert(cv.x.end(), {p, p}), cv.y.insert(cv.y.end(), {mid - half, mid + half});
    }
    c.curves.push_back(cv);
  }
  return c;
}

}  // namespace dmi::render
