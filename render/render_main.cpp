#include "render/render_main.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cerrno>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <vector>

#include "design/design.hpp"
#include "design/members_json.hpp"
#include "design/phases.hpp"
#include "design/verdict.hpp"
#include "design/loads.hpp"
#include "engine/common/error.hpp"
#include "engine/io/results_writer.hpp"
#include "render/charts.hpp"
#include "render/field.hpp"
#include "render/frame_state.hpp"
#include "render/picture_helper.hpp"
#include "render/solid.hpp"

#include <fcntl.h>
#include <unistd.h>

#include "core/variants.hpp"

namespace dmi::render {

using nlohmann::json;
namespace fs = std::filesystem;

std::vector<RunData> load_runs(const std::string& out_dir, design::DesignDocument& design_doc) {
  std::error_code ec;
  const fs::path d = fs::is_directory(out_dir, ec) ? fs::path(out_dir) : fs::path(out_dir).parent_path();
  const std::vector<std::pair<std::string, fs::path>> files = variant_results(d);
  if (files.empty()) throw InputError(out_dir + ": no results.h5 (nor with_buffer/ and without_buffer/ holding one); run damimpact simulate or run first");
  std::vector<RunData> runs;
  for (const auto& [variant, f] : files) {
    RunData r;
    r.file = f.string();
    try {
      r.results = read_results(r.file, true);
    } catch (const std::exception& e) {
      throw InputError(e.what());
    }
    r.variant = r.results.info.variant.empty() ? variant : r.results.info.variant;
    if (r.results.info.structure) {
      try {
        r.frame = design::frame_info(*r.results.info.structure, r.file, design::Limits{});
      } catch (const std::exception& e) {
        throw InputError(e.what());
      }
    }
    runs.push_back(std::move(r));
  }
  // design.json beside the results, else the checks with default limits.
  std::optional<design::DesignDocument> written;
  if (fs::exists(d / "design.json")) {
    try {
      written = design::read_design_json((d / "design.json").string());
    } catch (const std::exception& e) {
      throw InputError(std::string(e.what()) + "; re-run damimpact check");
    }
  }
  std::vector<design::RunDesign> entries;
  std::vector<bool> from_file;
  for (auto& r : runs) {
    const design::RunDesign* found = nullptr;
    if (written)
      for (const design::RunDesign& e : written->runs)
        if (e.variant == r.variant) found = &e;
    try {
      r.design = found ? *found : design::design_run(r.results, design::Limits{}, r.file);
    } catch (const std::exception& e) {
      throw InputError(e.what());
    }
    entries.push_back(r.design);
    from_file.push_back(found != nullptr);
  }
  // Which run is the bare reference of a comparison: as design.json says, else design_document's pairing.
  design::DesignDocument paired = design::design_document(std::move(entries), design::Limits{}, "");
  for (std::size_t i = 0; i < runs.size(); ++i)
    if (!from_file[i]) runs[i].design.reference = paired.runs[i].reference;
  design_doc = written ? std::move(*written) : std::move(paired);
  return runs;
}

std::string nice_variant(const std::string& v) { return v == "with_buffer" ? "with buffer" : v == "without_buffer" ? "without buffer" : ""; }

std::array<unsigned char, 3> colour(std::size_t i) {
  static const std::array<unsigned char, 3> c[] = {{31, 119, 180}, {255, 127, 14}, {44, 160, 44}, {148, 103, 189}};
  return c[i % 4];
}

namespace {

std::size_t nearest_snapshot(const Results& r, double t) {
  std::size_t best = 0;
  for (std::size_t k = 0; k < r.snapshots.size(); ++k)
    if (std::abs(r.snapshots[k].time - t) < std::abs(r.snapshots[best].time - t)) best = k;
  return best;
}

std::string ms(double t) {
  char b[32];
  std::snprintf(b, sizeof b, "%.1f ms", t * 1e3);
  return b;
}


std::optional<design::Check> plotted_check(const RunData& run);

// The contact's peak instant and its pulse (design.json contact), or `otherwise` without a recorded contact.
double peak_time_or(const RunData& r, double otherwise) {
  const design::Contact& c = r.design.contact;
  return c.present && c.peak_time_s >= 0 ? c.peak_time_s : otherwise;
}
double pulse_start_or(const RunData& r, double otherwise) { return r.design.contact.present ? r.design.contact.pulse_start_s : otherwise; }
double pulse_end_or(const RunData& r, double otherwise) { return r.design.contact.present ? r.design.contact.pulse_end_s : otherwise; }

// The governing instant of the stress field: the governing check's time when it is a check of the members' or the
// solid's stresses, else the most utilised member check's (a check of the dam on its foundation or of the struck face
// has no field to show), else the contact peak, else the end.
double governing_time(const RunData& r) {
  const double end = r.results.time.empty() ? 0.0 : r.results.time.back();
  const double peak = peak_time_or(r, end);
  const std::optional<design::Check>& g = r.design.verdict.governing;
  const auto time_or_peak = [peak](const design::Check& c) { return c.time_s >= 0 ? c.time_s : peak; };
  if (g && g->material != "foundation" && g->id.rfind("local_", 0) != 0) return time_or_peak(*g);
  const std::optional<design::Check> c = plotted_check(r);
  return c ? time_or_peak(*c) : peak;
}

// The instant of a run's largest member fibre stress |sigma| (design.json envelopes), where the members carry the most;
// NaN without members.
struct MemberPeak {
  double time = std::nan(""), value = 0;
  std::string member;
};

MemberPeak member_peak(const RunData& r) {
  MemberPeak p;
  for (const design::MemberEnvelope& m : r.design.members)
    for (const design::Station& st : m.stations)
      for (const design::Extreme* e : {&st.sigma_tension, &st.sigma_compression}) {
        const double v = e->set ? std::abs(e->value) : 0.0;
        if (v > p.value) p = {e->time, v, m.name};
      }
  return p;
}

// What a robust particle scale left out, for the caption.
std::string scale_note(const FieldImage& f, const std::vector<Panel>& panels) {
  if (!f.clipped) return "";
  char b[200];
  std::snprintf(b, sizeof b, "; particle colours up to the 99th percentile, %.3g MPa; the largest particle value, %.3g MPa, is at %s",
                f.particles.hi / 1e6, f.peak.value / 1e6, f.peak.where().c_str());
  std::string s = b;
  if (panels.size() > 1) s += " (" + panels[f.peak.panel].heading + ")";
  return s;
}



// The y of the impact point: the force-weighted y of the contact loads at the peak, else the middle of the frame's
// nodes, else of the grid's particles at the start.
double impact_y(const RunData& r) {
  if (const auto& pc = r.results.info.peak_contact) {
    double w = 0, wy = 0;
    for (const ContactLoadAt& l : pc->loads) {
      if (l.point.size() != 3) continue;
      double f2 = 0;
      for (double c : l.force) f2 += c * c;
      w += std::sqrt(f2), wy += std::sqrt(f2) * l.point[1];
    }
    if (w > 0) return wy / w;
  }
  double lo = 1e300, hi = -1e300;
  if (r.frame)
    for (const auto& x : r.frame->nodes) lo = std::min(lo, x[1]), hi = std::max(hi, x[1]);
  return lo <= hi ? 0.5 * (lo + hi) : 0.0;
}

// A member check with a time history to plot: the governing one when it is a member check, else the member check
// with the largest utilisation.
std::optional<design::Check> plotted_check(const RunData& run) {
  std::optional<design::Check> best;
  for (const design::Check& c : run.design.checks) {
    if (c.id.rfind("solid", 0) == 0 || c.id == "steel_section_class" || c.id == "concrete_punching" || c.position < 0) continue;
    if (!best || c.utilisation > best->utilisation) best = c;
  }
  return best;
}

}  // namespace

Manifest render_runs(const std::vector<RunData>& runs, const design::DesignDocument& design_doc, const std::string& image_dir,
                     const RenderOptions& o, PictureHelper* helper) {
  fs::create_directories(image_dir);
  const design::Limits& limits = design_doc.limits;
  Manifest manifest;
  manifest.quantity = o.quantity;
  const auto t0 = std::chrono::steady_clock::now();
  const bool assist = o.helper_of > 0, shared = assist || (helper && helper->active());
  const fs::path claims = assist ? fs::path(o.claims) : shared ? fs::path(helper->claims()) : fs::path();
  int picture = 0;
  auto mine = [&] {  // the pictures in the order below; shared, the first process to create a picture's claim draws it
    const int k = picture++;
    if (!shared) return true;
    const int fd = ::open((claims / std::to_string(k)).c_str(), O_CREAT | O_EXCL | O_WRONLY | O_CLOEXEC, 0644);
    if (fd >= 0) return ::close(fd), true;
    return errno != EEXIST && !assist;  // no claim possible: this process draws it, the helper none
  };
  struct StopHelper {  // an error here: the helper ends before this process goes on (a report without pictures)
    PictureHelper* h;
    const std::string& dir;
    ~StopHelper() {
      if (h) h->stop(dir);
    }
  } stop_helper{shared && !assist ? helper : nullptr, image_dir};
  std::vector<std::string> rendered;  // shared: told when the helper has ended
  auto add = [&](const std::string& file, const std::string& kind, const std::string& variant, const std::string& caption, int w, int h,
                 const FieldImage* f) {
    Picture p{file, kind, variant, caption, w, h, std::nullopt, std::nullopt};
    if (f) p.field = Picture::Field{f->particles.lo, f->particles.hi, f->members.lo, f->members.hi, f->deform_scale, o.quantity};
    manifest.images.push_back(p);
    if (shared) rendered.push_back((fs::path(image_dir) / file).string());
    else if (!o.quiet) std::printf("rendered %s\n", (fs::path(image_dir) / file).string().c_str());
  };
  const std::string qlabel = quantity_label(o.quantity);
  // Field pictures per run: the governing instant, then initial / contact start / peak / rebound on one scale.
  for (const auto& r : runs) {
    if (r.results.snapshots.empty()) continue;
    const std::string tag = r.variant.empty() ? "run" : r.variant;
    const std::string name = r.results.info.scenario_name;
    const double tg = governing_time(r);
    const std::size_t sg = nearest_snapshot(r.results, tg);
    const design::FrameInfo* fr = r.frame ? &*r.frame : nullptr;
    const double ts = r.results.snapshots[sg].time;
    Panel p{&r.results, fr, sg, "t = " + ms(ts) + (std::abs(ts - tg) > 1e-4 ? " (the snapshot nearest " + ms(tg) + ")" : "")};
    FieldSpec spec;
    spec.quantity = o.quantity;
    const std::optional<design::Check>& g = r.design.verdict.governing;
    spec.title = name + ": " + qlabel + " near the governing instant (" + ms(tg) + (g ? ", " + g->title : "") + ")";
    spec.draw = mine();
    const std::string f1 = "field_" + tag + "_governing.png";
    const FieldImage gi = render_field({p}, spec, (fs::path(image_dir) / f1).string());
    add(f1, "field_governing", r.variant, spec.title + "; picture at the nearest snapshot, t = " + ms(r.results.snapshots[sg].time) + scale_note(gi, {p}),
        gi.width, gi.height, &gi);
    // 3D: the vertical section through the impact point at the contact peak (particles within a cell of it, members cut there).
    if (r.results.snapshots[sg].dim == 3) {
      const double tp = peak_time_or(r, tg);
      const std::size_t sp = nearest_snapshot(r.results, tp);
      FieldSpec cs = spec;
      cs.section_y = impact_y(r);
      char b[160];
      const double yc = std::round(*cs.section_y * 100) / 100 + 0.0;  // + 0.0: no "-0.00"
      std::snprintf(b, sizeof b, ", section y = %.2f m through the impact point, seen from -y, at the contact peak (%s)", yc, ms(tp).c_str());
      cs.title = name + ": " + qlabel + b;
      cs.draw = mine();
      const std::string f2 = "field_" + tag + "_section.png";
      const std::vector<Panel> one{{&r.results, fr, sp, "t = " + ms(r.results.snapshots[sp].time)}};
      const FieldImage ci = render_field(one, cs, (fs::path(image_dir) / f2).string());
      add(f2, "field_section", r.variant, cs.title + "; picture at the nearest snapshot, t = " + ms(r.results.snapshots[sp].time) + scale_note(ci, one),
          ci.width, ci.height, &ci);
    }
    // The sequence: initial state, contact start, contact peak, rebound (end of the pulse); for a surge, its phases.
    const double t_peak = peak_time_or(r, tg);
    const double t_start = pulse_start_or(r, 0.0), t_end = pulse_end_or(r, t_peak);
    std::vector<std::pair<std::string, std::size_t>> seq = {{"initial state", 0},
                                                            {"contact start", nearest_snapshot(r.results, t_start)},
                                                            {"contact peak", nearest_snapshot(r.results, t_peak)},
                                                            {"rebound", nearest_snapshot(r.results, t_end + 0.5 * (t_end - t_start))}};
    // A debris surge: its arrival, its peak and the deposit it leaves (the last snapshot), not a rebound.
    if (const auto& dp = r.design.debris_phases)
      seq = {{"initial state", 0},
             {"surge arrival", nearest_snapshot(r.results, dp->phases.arrival_s)},
             {"load peak", nearest_snapshot(r.results, dp->phases.peak_time_s)},
             {"deposit", r.results.snapshots.size() - 1}};
    // Members that yield keep a residual shape: the last snapshot shows it (the members' deformation scaled as in the
    // rest of the sequence).
    if (r.design.plastic && r.results.snapshots.size() > 1)
      seq.push_back({"residual shape (end of the run)", r.results.snapshots.size() - 1});
    std::vector<Panel> all;
    for (const auto& [what, s] : seq) all.push_back({&r.results, fr, s, ""});
    FieldSpec sspec = spec;
    sspec.particle_range = particle_range(all, o.quantity);
    sspec.member_range = member_range(all);
    std::set<std::size_t> done;
    int k = 0;
    for (const auto& [what, s] : seq) {
      if (!done.insert(s).second) continue;
      sspec.title = name + ": " + qlabel + ", " + what + " (t = " + ms(r.results.snapshots[s].time) + "), one colour scale for the sequence";
      sspec.draw = mine();
      const std::string f = "field_" + tag + "_seq" + std::to_string(k++) + ".png";
      const std::vector<Panel> one{{&r.results, fr, s, what + ", t = " + ms(r.results.snapshots[s].time)}};
      const FieldImage si = render_field(one, sspec, (fs::path(image_dir) / f).string());
      add(f, "field_sequence", r.variant, sspec.title + scale_note(si, one), si.width, si.height, &si);
    }
  }
  // The solid-FE dam body of each run (its load case with the largest principal tension).
  for (const auto& r : runs) {
    const std::string tag = r.variant.empty() ? "run" : r.variant;
    const std::string file = "solid_" + tag + ".png";
    const std::string title = r.results.info.scenario_name + ": solid-FE check of the dam body (linear, static, base fixed)";
    try {
      if (const auto sp = render_solid(r.results, title, (fs::path(image_dir) / file).string(), 2400, 1100, mine())) {
        char b[1024];
        std::snprintf(b, sizeof b,
                      "%s: load case '%s'; left the body seen from upstream and above, von Mises stress (up to %.3g MPa); right the "
                      "vertical section across the middle of the face (y = %.2f m), maximum principal stress; the largest principal tension, "
                      "%.3g MPa, is at x = %.2f, y = %.2f, z = %.2f m (x through the thickness, y across, z up)",
                      title.c_str(), sp->case_name.c_str(), sp->von_mises_max / 1e6, sp->section_y, sp->principal_max / 1e6, sp->principal_at[0],
                      sp->principal_at[1], sp->principal_at[2]);
        // The check's own number for this case (design.json, at the elements' Gauss points), beside the picture's nodal one.
        std::string caption = b;
        if (r.design.solid)
          for (const design::SolidDesignCase& c : r.design.solid->cases)
            if (c.name == sp->case_name) {
              char k[320];
              std::snprintf(k, sizeof k, "; the picture's colours are nodal values, extrapolated from the elements to the nodes: the "
                                         "check's principal tension, taken at the Gauss points (design.json), is %.3g MPa",
                            c.max_principal.value_Pa / 1e6);
              caption += k;
            }
        add(file, "field_solid", r.variant, caption, sp->width, sp->height, nullptr);
      }
    } catch (const std::runtime_error& e) {
      throw InputError(r.file + ": " + e.what());
    }
  }
  // With vs without buffer side by side on one colour scale, each run at its own peak member stress (comparable instants:
  // the governing instant may be another check's, e.g. the solid FE's), then the members' envelopes over the whole run.
  if (runs.size() == 2 && !runs[0].results.snapshots.empty() && !runs[1].results.snapshots.empty()) {
    std::vector<Panel> panels, envelope;
    std::string instants;
    bool members = true;
    for (const auto& r : runs) {
      const MemberPeak mp = member_peak(r);
      members = members && r.frame && std::isfinite(mp.time);
      const double t = std::isfinite(mp.time) ? mp.time : governing_time(r);
      const std::size_t s = nearest_snapshot(r.results, t);
      const std::string at = ms(r.results.snapshots[s].time);
      panels.push_back({&r.results, r.frame ? &*r.frame : nullptr, s, nice_variant(r.variant) + ", t = " + at});
      envelope.push_back({&r.results, r.frame ? &*r.frame : nullptr, s, nice_variant(r.variant) + ": member envelope", true});
      char b[160];
      if (std::isfinite(mp.time))
        std::snprintf(b, sizeof b, "%s%s at t = %s (peak member fibre stress %.3g MPa, %s, at %s)", instants.empty() ? "" : "; ",
                      nice_variant(r.variant).c_str(), at.c_str(), mp.value / 1e6, mp.member.c_str(), ms(mp.time).c_str());
      else
        std::snprintf(b, sizeof b, "%s%s at t = %s (its governing instant, %s)", instants.empty() ? "" : "; ", nice_variant(r.variant).c_str(), at.c_str(),
                      ms(governing_time(r)).c_str());
      instants += b;
    }
    FieldSpec spec;
    spec.quantity = o.quantity;
    spec.width = 2400, spec.height = 1100;
    std::string name = runs[0].results.info.scenario_name;
    if (const auto k = name.rfind(" (with buffer)"); k != std::string::npos && k + 14 == name.size()) name.erase(k);
    spec.title = name + ": " + qlabel + (members ? " at each run's peak member stress" : " near each run's governing instant") + ", one colour scale";
    spec.draw = mine();
    const FieldImage ci = render_field(panels, spec, (fs::path(image_dir) / "field_comparison.png").string());
    add("field_comparison.png", "field_comparison", "", spec.title + ": " + instants + scale_note(ci, panels), ci.width, ci.height, &ci);
    if (members && runs[0].frame->dim == 2) {  // the envelope colours a plane member's two faces; a space member's
                                               // vertices take the instant's section forces (not an envelope)
      spec.title = name + ": members coloured by their fibre-stress envelope over the run, one colour scale";
      spec.draw = mine();
      const FieldImage ei = render_field(envelope, spec, (fs::path(image_dir) / "field_envelope.png").string());
      add("field_envelope.png", "field_comparison", "",
          spec.title + " (at each face the largest |fibre stress| of any instant); particles at the instants of the comparison above" + scale_note(ei, envelope),
          ei.width, ei.height, &ei);
    }
  }
  // A chart as PNG and SVG into the images and the manifest.
  auto draw = [&](ChartSpec& spec, const std::string& name, const std::string& caption) {
    spec.svg_path = (fs::path(image_dir) / fs::path(name).replace_extension(".svg")).string();
    spec.draw = mine();
    render_chart(spec, (fs::path(image_dir) / name).string());
    add(name, "chart", "", caption, spec.width, spec.height, nullptr);
    manifest.images.back().vector_file = fs::path(spec.svg_path).filename().string();
  };
  // Charts: every run overlaid (the bare run dashed).
  auto overlay = [&](const std::string& file, const std::string& title, const std::string& ylabel, auto&& series_of, double scale,
                     std::vector<Curve> extra = {}, double x_max = 0) {
    ChartSpec c;
    c.x_max = x_max;
    c.title = title, c.x_label = "time [ms]", c.y_label = ylabel;
    for (std::size_t i = 0; i < runs.size(); ++i) {
      Curve cv;
      cv.label = runs[i].variant.empty() ? "simulation" : nice_variant(runs[i].variant);
      cv.color = colour(i);
      cv.dashed = runs[i].variant == "without_buffer";
      const std::vector<double> y = series_of(runs[i]);
      if (y.size() != runs[i].results.time.size()) continue;
      for (std::size_t k = 0; k < y.size(); ++k) cv.x.push_back(runs[i].results.time[k] * 1e3), cv.y.push_back(y[k] * scale);
      c.curves.push_back(cv);
    }
    // Runs of unlike magnitude (a bare impact's 25 MN beside a buffered 0.3 MN) get a panel of their own as well.
    ChartSpec small = c;
    small.curves = small_magnitude_curves(c.curves);
    for (auto& e : extra) c.curves.push_back(e);
    if (c.curves.empty()) return;
    draw(c, file, title);
    if (!small.curves.empty()) {
      small.title = title + ", the runs below a tenth of the largest peak";
      draw(small, fs::path(file).stem().string() + "_small.png", small.title);
    }
  };
  if (ChartSpec fp = face_profile_chart(runs); !fp.curves.empty()) {  // a bare impact's MPa beside a buffered kPa: panels of their own
    ChartSpec small = fp;
    small.curves = small_magnitude_curves(fp.curves, true);
    draw(fp, "chart_face_profile.png", fp.title);
    if (!small.curves.empty()) {
      small.title = "contact pressure on the struck face: the runs below a tenth of the largest";
      draw(small, "chart_face_profile_small.png", small.title);
    }
  }
  const bool frames = std::all_of(runs.begin(), runs.end(), [](const RunData& r) { return r.frame && !r.frame->supports.empty(); });
  if (frames) {
    // The contact chart ends a pulse length after the last run's pulse (in ms).
    double contact_end = 0;
    for (const auto& r : runs) {
      const double a = pulse_start_or(r, 0), b = pulse_end_or(r, 0);
      contact_end = std::max(contact_end, (b + std::max(b - a, 0.2 * b)) * 1e3);
    }
    if (contact_end >= runs[0].results.time.back() * 1e3) contact_end = 0;
    overlay("chart_contact_force.png", "contact force on the dam", "force [kN]", [](const RunData& r) { return design::contact_magnitude(r.results); },
            1e-3, {}, contact_end);
    const bool space = runs[0].frame->dim == 3;
    overlay("chart_base_shear.png", space ? "base shear (horizontal resultant of the support forces, |(sum Fx, sum Fy)|)" : "base shear (sum of the support forces Fx)",
            "shear [kN]", [](const RunData& r) { return design::base_history(r.results, *r.frame, r.file).shear(); }, 1e-3);
    overlay("chart_base_moment.png", space ? "overturning moment (|(Mx, My)| about the centroid of the supports)" : "base moment (about the centroid of the supports)",
            "moment [kN m]", [](const RunData& r) { return design::base_history(r.results, *r.frame, r.file).moment(); }, 1e-3);
    // The governing member check's demand at its station, with its capacity as a line.
    if (const std::optional<design::Check> c = plotted_check(runs[0])) {
      const std::string& unit = c->unit;
      const double scale = unit == "Pa" ? 1e-6 : unit == "N" ? 1e-3 : 1.0;
      const std::string ul = unit == "Pa" ? "MPa" : unit == "N" ? "kN" : "-";
      const std::string member = c->member, id = c->id;
      const double pos = c->position, tmax = runs[0].results.time.back() * 1e3;
      const design::Limits L = limits;
      overlay("chart_governing_demand.png", c->title + ", " + member + " at s = " + std::to_string(c->s_m).substr(0, 4) + " m", c->title + " [" + ul + "]",
              [&](const RunData& r) { return r.frame ? demand_history(r.results, *r.frame, member, pos, id, L) : std::vector<double>{}; }, scale,
              {limit_line("capacity " + std::to_string(c->capacity * scale).substr(0, 5) + " " + ul, c->capacity * scale, 0, tmax)});
    }
    // Stress envelope along the most utilised member (the dam's height for a concrete dam).
    if (const std::optional<design::Check> c = plotted_check(runs[0])) {
      const std::string member = c->member;
      ChartSpec e;
      e.title = "fibre stress envelope along " + member;
      e.x_label = "stress [MPa] (tension +)", e.y_label = "distance from the member start [m]";
      e.x_tight = false;
      double smax = 0;
      for (std::size_t i = 0; i < runs.size(); ++i)
        for (const design::MemberEnvelope& m : runs[i].design.members) {
          if (m.name != member) continue;
          Curve t, cpr;
          t.label = "max tension" + (runs[i].variant.empty() ? "" : ", " + nice_variant(runs[i].variant));
          cpr.label = "max compression" + (runs[i].variant.empty() ? "" : ", " + nice_variant(runs[i].variant));
          t.color = cpr.color = colour(i);
          t.dashed = cpr.dashed = runs[i].variant == "without_buffer";
          cpr.width = 2.0f;
          for (const design::Station& s : m.stations) {
            t.x.push_back((s.sigma_tension.set ? s.sigma_tension.value : 0.0) * 1e-6), t.y.push_back(s.s_m);
            cpr.x.push_back((s.sigma_compression.set ? s.sigma_compression.value : 0.0) * 1e-6), cpr.y.push_back(s.s_m);
            smax = std::max(smax, s.s_m);
          }
          e.curves.push_back(t), e.curves.push_back(cpr);
        }
      if (c->material == "concrete") {
        const double ft = limits.concrete.tensile_capacity() * 1e-6;
        e.curves.push_back(limit_line("tension limit", ft, 0, smax, true));
      }
      if (!e.curves.empty()) draw(e, "chart_envelope.png", e.title);
    }
  }
  if (assist) return manifest;  // the second process: the pictures only
  const bool helped = shared && helper->wait();
  stop_helper.h = nullptr;
  if (shared && !helped) {  // it failed: draw everything here (after removing what a picture it cut short left)
    helper->stop(image_dir);
    RenderOptions all = o;
    all.processes = 1;
    return render_runs(runs, design_doc, image_dir, all, nullptr);
  }
  for (const std::string& r : rendered)
    if (!o.quiet) std::printf("rendered %s\n", r.c_str());
  for (const Picture& p : manifest.images)
    for (const std::optional<std::string>& f : {std::optional<std::string>(p.file), p.vector_file})
      if (f && !fs::exists(fs::path(image_dir) / *f))
        throw std::runtime_error((fs::path(image_dir) / *f).string() + ": the picture was not written");
  manifest.render_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  manifest.processes = helped ? 2 : 1;
  std::ofstream(fs::path(image_dir) / "images.json") << to_json(manifest).dump(1) << "\n";
  return manifest;
}

std::vector<RunData> pictured_runs(const std::vector<RunData>& runs) {
  std::vector<RunData> plane;
  for (const RunData& r : runs)
    if (!is_space_variant(r.variant)) plane.push_back(r);
  return plane.empty() ? runs : plane;
}

json render_main(const std::string& out_dir, const RenderOptions& o) {
  PictureHelper helper(out_dir, o.quantity, o.helper_of > 0 ? 1 : o.processes);
  design::DesignDocument design_doc;
  const std::vector<RunData> runs = pictured_runs(load_runs(out_dir, design_doc));
  std::error_code ec;
  const fs::path d = fs::is_directory(out_dir, ec) ? fs::path(out_dir) : fs::path(out_dir).parent_path();
  return to_json(render_runs(runs, design_doc, (d / "images").string(), o, &helper));
}

}  // namespace dmi::render
