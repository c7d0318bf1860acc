#include "design/stability_record.hpp"

#include "design/record_reader.hpp"

#include <cmath>
#include <stdexcept>

namespace dmi::design {

using nlohmann::json;

using namespace record;

namespace {

json finite_or_null(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

json sample_json(const StabilityRecord::Sample& s) {
  return json{{"time_s", s.time_s}, {"N_N", s.N_N}, {"H_N", s.H_N}, {"sliding_factor", finite_or_null(s.sliding_factor)},
              {"overturning_factor", finite_or_null(s.overturning_factor)}, {"resultant_from_toe_m", finite_or_null(s.resultant_from_toe_m)},
              {"eccentricity_m", finite_or_null(s.eccentricity_m)}, {"compressed_fraction", s.compressed_fraction},
              {"toe_pressure_Pa", finite_or_null(s.toe_pressure_Pa)}, {"heel_pressure_Pa", finite_or_null(s.heel_pressure_Pa)}};
}

StabilityRecord::Sample sample_from(const json& j, const std::string& w) {
  StabilityRecord::Sample s;
  s.time_s = number(j, "time_s", w), s.N_N = number(j, "N_N", w), s.H_N = number(j, "H_N", w);
  s.sliding_factor = number_or(j, "sliding_factor", NAN, w), s.overturning_factor = number_or(j, "overturning_factor", NAN, w);
  s.resultant_from_toe_m = number_or(j, "resultant_from_toe_m", NAN, w), s.eccentricity_m = number_or(j, "eccentricity_m", NAN, w);
  s.compressed_fraction = number(j, "compressed_fraction", w);
  s.toe_pressure_Pa = number_or(j, "toe_pressure_Pa", NAN, w), s.heel_pressure_Pa = number_or(j, "heel_pressure_Pa", NAN, w);
  return s;
}

}  // namespace

json to_json(const StabilityRecord& s) {
  if (!s.not_assessed.empty()) return json{{"not_assessed", s.not_assessed}};
  const auto& d = s.dam;
  const auto& f = s.foundation;
  const auto& i = s.impact;
  return json{{"model", s.model},
              {"dam", {{"mass_kg", d.mass_kg}, {"weight_N", d.weight_N}, {"base_m", d.base_m}, {"width_m", d.width_m},
                       {"weight_lever_from_toe_m", d.weight_lever_from_toe_m}, {"centroid_height_m", d.centroid_height_m},
                       {"inertia_about_toe_kg_m2", d.inertia_about_toe_kg_m2}, {"critical_angle_rad", d.critical_angle_rad}}},
              {"foundation", {{"friction", f.friction}, {"cohesion_Pa", f.cohesion_Pa}, {"bearing_capacity_Pa", f.bearing_capacity_Pa},
                              {"uplift_factor", f.uplift_factor}, {"uplift_N", f.uplift_N}}},
              {"persistent", sample_json(s.persistent)},
              {"impact",
               {{"least_sliding_factor", sample_json(i.least_sliding_factor)},
                {"least_compressed_base", sample_json(i.least_compressed_base)},
                {"time_outside_middle_third_s", i.time_outside_middle_third_s},
                {"time_outside_base_s", i.time_outside_base_s},
                {"sliding_displacement_m", i.sliding_displacement_m},            // +inf: written null
                {"peak_rocking_rotation_rad", i.peak_rocking_rotation_rad}}}};
}

std::optional<StabilityRecord> stability_from_json(const json& j, const std::string& w) {
  if (j.is_null()) return std::nullopt;
  StabilityRecord s;
  if (j.is_object() && j.contains("not_assessed")) {
    const json& why = j["not_assessed"];
    if (!why.is_string()) throw std::runtime_error(w + ".not_assessed is not a string");
    s.not_assessed = why.get<std::string>();
    return s;
  }
  const json& model = field(j, "model", w);
  if (!model.is_string()) throw std::runtime_error(w + ".model is not a string");
  s.model = model.get<std::string>();
  const json& d = field(j, "dam", w);
  const std::string wd = w + ".dam";
  s.dam = {number(d, "mass_kg", wd), number(d, "weight_N", wd), number(d, "base_m", wd), number(d, "width_m", wd),
           number(d, "weight_lever_from_toe_m", wd), number(d, "centroid_height_m", wd), number(d, "inertia_about_toe_kg_m2", wd),
           number(d, "critical_angle_rad", wd)};
  const json& f = field(j, "foundation", w);
  const std::string wf = w + ".foundation";
  s.foundation = {number(f, "friction", wf), number(f, "cohesion_Pa", wf), number(f, "bearing_capacity_Pa", wf), number(f, "uplift_factor", wf),
                  number(f, "uplift_N", wf)};
  s.persistent = sample_from(field(j, "persistent", w), w + ".persistent");
  const json& i = field(j, "impact", w);
  const std::string wi = w + ".impact";
  s.impact.least_sliding_factor = sample_from(field(i, "least_sliding_factor", wi), wi + ".least_sliding_factor");
  s.impact.least_compressed_base = sample_from(field(i, "least_compressed_base", wi), wi + ".least_compressed_base");
  s.impact.time_outside_middle_third_s = number(i, "time_outside_middle_third_s", wi);
  s.impact.time_outside_base_s = number(i, "time_outside_base_s", wi);
  s.impact.sliding_displacement_m = number_or(i, "sliding_displacement_m", INFINITY, wi);
  s.impact.peak_rocking_rotation_rad = number_or(i, "peak_rocking_rotation_rad", INFINITY, wi);
  return s;
}

}  // namespace dmi::design
