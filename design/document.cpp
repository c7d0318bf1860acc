// design.json as a whole: runs, the with/without-buffer comparison and the verdict (docs/design-json.md).
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>

#include "core/variants.hpp"
#include "design/design.hpp"
#include "design/loads.hpp"
#include "design/verdict.hpp"
#include "design/design_document.hpp"

namespace dmi::design {

using nlohmann::json;
namespace fs = std::filesystem;

namespace {

double finite_or_nan(double v) { return std::isfinite(v) ? v : NAN; }

// The largest value of a member peak over all members and stations (sign: +1 max of value, -1 max of -value).
double member_max(const RunDesign& run, Extreme Station::*peak, double sign) {
  double best = NAN;
  for (const MemberEnvelope& m : run.members)
    for (const Station& s : m.stations) {
      const Extreme& e = s.*peak;
      if (e.set && (std::isnan(best) || sign * e.value > best)) best = sign * e.value;
    }
  return best;
}

double contact_peak(const RunDesign& r) { return r.contact.present ? r.contact.peak_N : NAN; }
double contact_impulse(const RunDesign& r) { return r.contact.present ? r.contact.impulse_magnitude() : NAN; }
double level_utilisation(const RunDesign& r, const char* level) {
  const auto l = r.verdict.levels.find(level);
  return l == r.verdict.levels.end() ? NAN : l->second.max_utilisation();
}

// The output folder a run's variant sits in: OUT/results.h5 for the variant "", OUT/<variant>/results.h5 otherwise.
std::string root_folder(const RunDesign& r) {
  const fs::path p = fs::path(r.results_file).parent_path();
  return (r.variant.empty() ? p : p.parent_path()).string();
}

// The plane model's governing numbers beside its 3D model's (compare_3d), one pair of runs.
PlaneAndSpace::Pair plane_and_space(const RunDesign& plane, const RunDesign& space) {
  struct Q { const char* id; const char* title; const char* unit; std::function<double(const RunDesign&)> get; };
  auto level = [](const char* l) { return [l](const RunDesign& r) { return level_utilisation(r, l); }; };
  const std::vector<Q> qs = {
      {"base_shear", "peak base shear", "N", [](const RunDesign& r) { return r.base_abs_max(shear_key(r.dim())).value_or(NAN); }},
      {"base_moment", "peak base moment", "N m", [](const RunDesign& r) { return r.base_abs_max(moment_key(r.dim())).value_or(NAN); }},
      {"contact_force", "peak contact force", "N", contact_peak},
      {"contact_impulse", "contact impulse", "N s", contact_impulse},
      {"serviceability", "governing utilisation, serviceability", "-", level("serviceability")},
      {"ultimate", "governing utilisation, ultimate", "-", level("ultimate")},
      {"sliding", "sliding under the impact", "m", [](const RunDesign& r) { return r.stability ? finite_or_nan(r.stability->impact.sliding_displacement_m) : NAN; }},
      {"rocking", "rocking about the toe", "rad", [](const RunDesign& r) { return r.stability ? finite_or_nan(r.stability->impact.peak_rocking_rotation_rad) : NAN; }},
  };
  PlaneAndSpace::Pair pair{plane.variant, plane.verdict.passed, space.verdict.passed, {}};
  for (const Q& q : qs) {
    const double a = q.get(plane), b = q.get(space);
    if (std::isnan(a) || std::isnan(b)) continue;
    pair.quantities.push_back({q.id, q.title, q.unit, a, b, b != 0 ? std::optional<double>(a / b) : std::nullopt});
  }
  return pair;
}

}  // namespace

std::optional<PlaneAndSpace> plane_and_space_section(const std::vector<RunDesign>& runs) {
  PlaneAndSpace out;
  for (const RunDesign& s : runs) {
    if (!is_space_variant(s.variant)) continue;
    for (const RunDesign& p : runs)
      if (p.variant == plane_variant(s.variant) && root_folder(p) == root_folder(s)) out.pairs.push_back(plane_and_space(p, s));
  }
  if (out.pairs.empty()) return std::nullopt;
  out.note = "ratio = plane / 3D. The plane model strikes a width of the dam with a cylinder of the boulder's mass; the 3D "
             "model strikes the whole crest with the sphere. Both are judged: the verdict is the worse of the two.";
  return out;
}

BufferComparison compare_runs(const RunDesign& with, const RunDesign& without) {
  struct Q { const char* id; const char* title; const char* unit; std::function<double(const RunDesign&)> get; };
  auto abs_m = [](const RunDesign& r) {
    const double a = member_max(r, &Station::M_max, 1), b = member_max(r, &Station::M_min, -1);
    return std::isnan(a) ? b : std::isnan(b) ? a : std::max(a, b);
  };
  auto peak = [](Extreme Station::*q, double sign) { return [q, sign](const RunDesign& r) { return member_max(r, q, sign); }; };
  const std::vector<Q> qs = {
      {"base_shear", "peak base shear (plane |sum Fx|, space |(sum Fx, sum Fy)|)", "N", [](const RunDesign& r) { return r.base_abs_max(shear_key(r.dim())).value_or(NAN); }},
      {"base_moment", "peak base moment (plane |sum M|, space the overturning |(Mx, My)|)", "N m",
       [](const RunDesign& r) { return r.base_abs_max(moment_key(r.dim())).value_or(NAN); }},
      {"contact_force", "peak contact force", "N", contact_peak},
      {"contact_impulse", "contact impulse", "N s", contact_impulse},
      {"contact_duration", "contact pulse duration", "s",
       [](const RunDesign& r) { return r.contact.present ? r.contact.pulse_end_s - r.contact.pulse_start_s : NAN; }},
      {"member_moment", "peak member |M|", "N m", abs_m},
      {"member_shear", "peak member |V|", "N", peak(&Station::V_abs, 1)},
      {"flexural_tension", "peak fibre tension", "Pa", peak(&Station::sigma_tension, 1)},
      {"fibre_compression", "peak fibre compression", "Pa", peak(&Station::sigma_compression, -1)},
      {"member_von_mises", "peak member von Mises", "Pa", peak(&Station::von_mises, 1)},
      {"max_utilisation", "largest utilisation", "-", [](const RunDesign& r) { return r.verdict.max_utilisation(); }},
  };
  BufferComparison out;
  auto row = [&](const std::string& id, const std::string& title, const std::string& unit, double a, double b) {
    if (std::isnan(a) || std::isnan(b)) return;
    out.quantities.push_back({id, title, unit, a, b, b != 0 ? std::optional<double>(100 * (b - a) / b) : std::nullopt});
  };
  for (const auto& q : qs) row(q.id, q.title, q.unit, q.get(with), q.get(without));
  if (with.solid && without.solid)
    for (const SolidDesignCase& cw : with.solid->cases)
      for (const SolidDesignCase& cb : without.solid->cases)
        if (cw.name == cb.name) {
          const std::string& n = cw.name;
          row("solid_von_mises:" + n, "solid FE von Mises (" + n + ")", "Pa", cw.von_mises.value_Pa, cb.von_mises.value_Pa);
          row("solid_max_principal:" + n, "solid FE max principal (" + n + ")", "Pa", cw.max_principal.value_Pa, cb.max_principal.value_Pa);
        }
  out.note = "reduction_percent = 100 (without - with) / without; a negative value is an increase (the buffer lengthens the contact pulse)";
  return out;
}

namespace {

// The document's verdict: the judged runs' checks summed, the governing check the largest utilisation of any; each level
// and each design situation likewise.
Verdict document_verdict(const std::vector<RunDesign>& runs, const Limits& limits) {
  Verdict d;
  d.document = true, d.judged_levels = limits.verdict_level;
  for (const char* level : {"serviceability", "ultimate"}) d.levels[level] = {};
  for (const char* situation : {"persistent", "accidental"}) d.situations[situation] = {};
  const auto add = [](LevelVerdict& into, const LevelVerdict& v) {
    into.checks += v.checks, into.failed += v.failed, into.passed = into.failed == 0;
    if (v.governing && (!into.governing || v.governing->utilisation > into.governing->utilisation)) into.governing = v.governing;
  };
  for (const RunDesign& r : runs) {
    if (r.reference) continue;
    const Verdict& v = r.verdict;
    const double before = d.governing ? d.governing->utilisation : -INFINITY;
    add(d, v);
    if (v.governing && v.governing->utilisation > before) d.governing_variant = r.variant, d.governing_results_file = r.results_file;
    for (auto& [name, l] : d.levels) add(l, v.levels.at(name));
    for (auto& [name, l] : d.situations) add(l, v.situations.at(name));
    d.runs_judged += (d.runs_judged.empty() ? "" : ", ") + (r.variant.empty() ? r.results_file : r.variant);
  }
  d.status = d.checks == 0 ? "no_checks" : d.failed == 0 ? "pass" : "fail";
  return d;
}

}  // namespace

DesignDocument design_document(std::vector<RunDesign> runs, const Limits& limits, const std::string& software_version) {
  DesignDocument doc;
  doc.software_version = software_version, doc.limits = limits;
  // Pair the variants of one comparison folder (OUT/with_buffer, OUT/without_buffer), within one model (plane, or the
  // 3D one of compare_3d): the bare run of a pair is the reference; every other run is judged.
  for (RunDesign& r : runs) r.reference = false;
  for (RunDesign& bare : runs) {
    if (plane_variant(bare.variant) != "without_buffer") continue;
    const std::string with = is_space_variant(bare.variant) ? space_variant("with_buffer") : "with_buffer";
    for (const RunDesign& w : runs)
      if (w.variant == with && root_folder(w) == root_folder(bare)) {
        bare.reference = true;
        if (!doc.comparison && !is_space_variant(bare.variant)) doc.comparison = compare_runs(w, bare);
      }
  }
  doc.plane_and_space = plane_and_space_section(runs);
  doc.verdict = document_verdict(runs, limits);
  doc.runs = std::move(runs);
  return doc;
}

}  // namespace dmi::design
