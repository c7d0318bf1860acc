#include "sweep/summary.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "render/charts.hpp"
#include "render/report.hpp"

namespace dmi::sweep {
namespace fs = std::filesystem;
using json = nlohmann::json;

namespace {

const char* kVariantOrder[] = {"with_buffer", "without_buffer", "run"};

std::vector<std::string> variant_labels(const std::vector<SweepRow>& rows) {
  std::set<std::string> seen;
  for (const SweepRow& r : rows)
    for (const auto& [k, v] : r.variants) seen.insert(k);
  std::vector<std::string> v;
  for (const char* l : kVariantOrder)
    if (seen.erase(l)) v.push_back(l);
  v.insert(v.end(), seen.begin(), seen.end());
  return v;
}

// A parameter value on a chart axis: a number, the length of a vector of numbers (a velocity), else nothing.
bool axis_value(const json& v, double* x) {
  if (v.is_number()) return *x = v.get<double>(), true;
  if (!v.is_array() || v.empty()) return false;
  double s = 0;
  for (const json& c : v) {
    if (!c.is_number()) return false;
    s += c.get<double>() * c.get<double>();
  }
  return *x = std::sqrt(s), true;
}

// A column heading for a parameter: its last pointer token, or the last two when another parameter ends the same.
std::string short_name(const std::string& ptr, const std::vector<std::string>& all) {
  auto tail = [](const std::string& p, int n) {
    std::size_t pos = p.size();
    for (int i = 0; i < n && pos != std::string::npos && pos > 0; ++i) pos = p.rfind('/', pos - 1);
    return pos == std::string::npos ? p : p.substr(pos + 1);
  };
  for (int n = 1; n < 8; ++n) {
    int same = 0;
    for (const std::string& q : all) same += tail(q, n) == tail(ptr, n);
    if (same == 1) return tail(ptr, n);
  }
  return ptr;
}

std::string csv_field(const json& v) {
  if (v.is_null()) return "";
  if (v.is_number_float()) {
    char b[32];
    std::snprintf(b, sizeof b, "%.10g", v.get<double>());
    return b;
  }
  const std::string s = v.is_string() ? v.get<std::string>() : v.dump();
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

std::string esc(const std::string& s) {
  std::string o;
  for (char c : s) o += c == '<' ? "&lt;" : c == '>' ? "&gt;" : c == '&' ? "&amp;" : c == '"' ? "&quot;" : std::string(1, c);
  return o;
}

std::string fmt(const json& v, const char* f = "%.3g") {
  if (!v.is_number()) return v.is_null() ? "–" : esc(v.is_string() ? v.get<std::string>() : v.dump());
  char b[48];
  std::snprintf(b, sizeof b, f, v.get<double>());
  return b;
}

// The case's value of parameter ptr (null when the row has none).
const json& param(const SweepRow& r, const std::string& ptr) {
  static const json none;
  const auto it = r.parameters.find(ptr);
  return it == r.parameters.end() ? none : it->second;
}

// A variant's figures, empty where the case has no such variant.
VariantFigures figures(const SweepRow& r, const std::string& label) {
  const auto it = r.variants.find(label);
  return it == r.variants.end() ? VariantFigures{} : it->second;
}

template <class T> json or_null(const std::optional<T>& v) { return v ? json(*v) : json(nullptr); }

std::string file_b64(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream ss;
  ss << in.rdbuf();
  return render::base64(ss.str());
}

// Charts per numeric parameter: governing utilisation, base shear and base moment, one point set per variant.
std::vector<std::pair<std::string, std::string>> charts(const SweepSummary& s, const fs::path& images) {
  std::vector<std::pair<std::string, std::string>> made;  // file, caption
  const auto labels = variant_labels(s.cases);
  static const std::array<unsigned char, 3> pal[] = {{31, 119, 180}, {255, 127, 14}, {44, 160, 44}, {148, 103, 189},
                                                     {140, 86, 75}, {227, 119, 194}, {127, 127, 127}, {23, 190, 207}};
  struct Q { const char* key; const char* title; const char* unit; double scale; std::optional<double> VariantFigures::*field; };
  const Q qs[] = {{"max_utilisation", "largest utilisation", "-", 1, &VariantFigures::max_utilisation},
                  {"base_shear_N", "peak base shear", "kN", 1e-3, &VariantFigures::base_shear_N},
                  {"base_moment_Nm", "peak base moment", "kN m", 1e-3, &VariantFigures::base_moment_Nm}};
  int p_index = 0;
  for (const std::string& ptr : s.parameters) {
    ++p_index;
    for (const Q& q : qs) {
      render::ChartSpec c;
      c.title = std::string(q.title) + " against " + ptr;
      c.x_label = ptr, c.y_label = std::string(q.title) + " [" + q.unit + "]";
      c.width = 1400, c.height = 800;
      double lo = INFINITY, hi = -INFINITY;
      // One line per variant and combination of the other parameters (e.g. utilisation against speed, one line per
      // buffer thickness), without_buffer dashed.
      std::vector<std::string> others;  // the other parameters that vary
      for (const std::string& q2 : s.parameters) {
        std::set<std::string> vals;
        for (const SweepRow& row : s.cases) vals.insert(param(row, q2).dump());
        if (q2 != ptr && vals.size() > 1) others.push_back(q2);
      }
      std::vector<std::string> keys;
      std::map<std::string, render::Curve> series;
      std::map<std::string, std::size_t> colour;  // same colour for the with/without pair of one combination
      for (const SweepRow& row : s.cases) {
        double x;
        if (!axis_value(param(row, ptr), &x)) continue;
        std::string group;
        for (const auto& o : others) group += (group.empty() ? "" : ", ") + short_name(o, s.parameters) + " " + param(row, o).dump();
        for (std::size_t l = 0; l < labels.size(); ++l) {
          const auto v = row.variants.find(labels[l]);
          if (v == row.variants.end() || !(v->second.*q.field)) continue;
          const double y = *(v->second.*q.field);
          const std::string key = labels[l] + (group.empty() ? "" : ", " + group);
          auto [it, fresh] = series.try_emplace(key);
          render::Curve& cv = it->second;
          if (fresh) {
            keys.push_back(key);
            colour.emplace(group, colour.size());
            cv.color = pal[colour[group] % 8];
            cv.label = labels.size() == 1 && labels[0] == "run" ? (group.empty() ? "simulation" : group) : key;
            cv.dashed = labels[l] == "without_buffer";
          }
          cv.x.push_back(x), cv.y.push_back(y * q.scale);
          lo = std::min(lo, x), hi = std::max(hi, x);
        }
      }
      for (std::size_t i = 0; i < keys.size() && i < 12; ++i) {
        render::Curve& cv = series[keys[i]];  // points in x order, a line through them
        std::vector<std::pair<double, double>> xy;
        for (std::size_t k = 0; k < cv.x.size(); ++k) xy.emplace_back(cv.x[k], cv.y[k]);
        std::sort(xy.begin(), xy.end());
        for (std::size_t k = 0; k < xy.size(); ++k) cv.x[k] = xy[k].first, cv.y[k] = xy[k].second;
        cv.points = cv.x.size() < 2;
        c.curves.push_back(std::move(cv));
      }
      if (c.curves.empty() || !(hi > lo)) continue;
      if (std::string(q.key) == "max_utilisation") c.curves.push_back(render::limit_line("limit 1.0", 1.0, lo, hi));
      const std::string name = "param" + std::to_string(p_index) + "_" + q.key + ".png";
      try {
        render::render_chart(c, (images / name).string());
        made.emplace_back(name, c.title);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "damimpact: warning: chart %s not drawn (%s)\n", name.c_str(), e.what());
      }
    }
  }
  return made;
}

std::string html(const SweepSummary& s, const std::vector<std::pair<std::string, std::string>>& figs, const fs::path& images) {
  const auto labels = variant_labels(s.cases);
  const int cases = static_cast<int>(s.cases.size());
  std::ostringstream h;
  h << "<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>" << esc(s.name) << " — sweep summary</title><style>"
    << render::kReportCss << "</style></head><body>\n";
  h << "<p class=\"kicker\">damimpact " << esc(s.software_version) << " · parametric study</p><h1>" << esc(s.name) << "</h1>\n";
  const bool all_pass = s.passed == cases;
  h << "<div class=\"verdict " << (s.failed_runs > 0 ? "none" : all_pass ? "pass" : "fail") << "\"><div class=\"verdict-word\">" << s.passed
    << " / " << cases << "</div><div class=\"verdict-text\">cases pass every design check"
    << (s.failed_runs > 0 ? "; " + std::to_string(s.failed_runs) + " case(s) could not be run (see the table)" : std::string()) << ".</div></div>\n";
  h << "<table class=\"kv\"><tr><th>sweep file</th><td class=\"mono\">" << esc(s.sweep_file) << "</td></tr><tr><th>base scenario</th><td class=\"mono\">"
    << esc(s.base_file) << "</td></tr><tr><th>parameters</th><td class=\"mono\">";
  for (const std::string& p : s.parameters) h << esc(p) << "<br>";
  h << "</td></tr><tr><th>ranks × threads</th><td>" << s.ranks << " × " << s.threads_per_rank << "</td></tr><tr><th>wall time</th><td>"
    << fmt(s.wall_seconds, "%.1f") << " s (" << fmt(s.cases_per_hour, "%.1f") << " cases per hour)</td></tr></table>\n";
  h << "<h2>Design envelope</h2><p class=\"lead\">Every combination, its verdict and its largest utilisation (the design run: with buffer "
       "in a comparison). A case passes when every check of its design run has utilisation ≤ 1.</p>\n";
  h << "<table class=\"grid\"><thead><tr><th>case</th>";
  for (const std::string& p : s.parameters) h << "<th>" << esc(short_name(p, s.parameters)) << "</th>";
  h << "<th>verdict</th>";
  for (const auto& l : labels) h << "<th class=\"num\">utilisation " << esc(l) << "</th><th class=\"num\">base shear " << esc(l) << " [kN]</th>";
  h << "<th>governing</th></tr></thead><tbody>\n";
  for (const SweepRow& r : s.cases) {
    h << "<tr><td>" << esc(r.case_name) << "</td>";
    for (const std::string& p : s.parameters) h << "<td class=\"mono\">" << esc(param(r, p).dump()) << "</td>";
    const std::string st = r.status == "failed" ? "could not run" : r.verdict.value_or("–");
    h << "<td class=\"" << (st == "pass" ? "ok" : "fail") << "\"><b>" << esc(st) << "</b>";
    if (r.error) h << "<br><span class=\"small\">" << esc(*r.error) << "</span>";
    h << "</td>";
    for (const auto& l : labels) {
      const VariantFigures v = figures(r, l);
      h << "<td class=\"num\">" << fmt(or_null(v.max_utilisation), "%.2f") << "</td><td class=\"num\">"
        << (v.base_shear_N ? fmt(*v.base_shear_N / 1e3, "%.1f") : "–") << "</td>";
    }
    h << "<td class=\"small\">" << (r.governing ? esc(r.governing->id + " (" + r.governing->member + ")") : "–") << "</td></tr>\n";
  }
  h << "</tbody></table>\n<h2>Charts</h2>\n";
  if (figs.empty()) h << "<p>No chart: no parameter with numeric values and two or more distinct values, or no case ran.</p>";
  for (const auto& [file, cap] : figs)
    h << "<figure><img style=\"width:100%\" src=\"data:image/png;base64," << file_b64(images / file) << "\"><figcaption class=\"small\">"
      << esc(cap) << "</figcaption></figure>\n";
  h << "<p class=\"small\">Per-case outputs: cases/&lt;case&gt;/ (scenario.json, results.h5, design.json, report.html). Data: summary.json, "
       "summary.csv.</p></body></html>\n";
  return h.str();
}

}  // namespace

SweepSummary summary_document(const SweepSpec& spec, std::vector<SweepRow> rows, const SweepRun& run, const std::string& version) {
  SweepSummary s;
  s.software_version = version, s.name = spec.name, s.sweep_file = spec.file, s.base_file = spec.base_file, s.parameters = spec.parameters;
  s.ranks = run.ranks, s.threads_per_rank = run.threads_per_rank, s.wall_seconds = run.wall_seconds;
  s.cases_per_hour = run.wall_seconds > 0 ? 3600.0 * double(rows.size()) / run.wall_seconds : 0.0;
  for (const SweepRow& r : rows) {
    s.passed += r.verdict == "pass";
    s.failed_runs += r.status == "failed";
    s.reused += r.status == "reused";
  }
  s.cases = std::move(rows);
  return s;
}

std::string summary_csv(const SweepSummary& s) {
  const auto labels = variant_labels(s.cases);
  std::ostringstream o;
  o << "case";
  for (const std::string& p : s.parameters) o << "," << csv_field(p);
  bool grid = false;  // a sweep with grid_study: the conservative bound u (1 + GCI) of each case
  for (const SweepRow& r : s.cases) grid = grid || r.utilisation_bound.has_value();
  o << ",status,verdict,max_utilisation" << (grid ? ",utilisation_bound" : "") << ",governing_check,governing_member,governing_variant";
  for (const auto& l : labels) o << "," << l << "_max_utilisation," << l << "_contact_peak_N," << l << "_base_shear_N," << l << "_base_moment_Nm";
  o << ",wall_seconds,error\n";
  for (const SweepRow& r : s.cases) {
    o << csv_field(r.case_name);
    for (const std::string& p : s.parameters) o << "," << csv_field(param(r, p));
    const auto gov = [&](std::string Governing::*f) { return r.governing ? json(*r.governing.*f) : json(nullptr); };
    o << "," << csv_field(r.status) << "," << csv_field(or_null(r.verdict)) << "," << csv_field(or_null(r.max_utilisation)) << ","
      << (grid ? csv_field(or_null(r.utilisation_bound)) + "," : "") << csv_field(gov(&Governing::id)) << "," << csv_field(gov(&Governing::member)) << ","
      << csv_field(gov(&Governing::variant));
    for (const auto& l : labels) {
      const VariantFigures v = figures(r, l);
      for (const std::optional<double>* f : {&v.max_utilisation, &v.contact_peak_N, &v.base_shear_N, &v.base_moment_Nm}) o << "," << csv_field(or_null(*f));
    }
    o << "," << csv_field(r.wall_seconds) << "," << csv_field(or_null(r.error)) << "\n";
  }
  return o.str();
}

void write_summary(const SweepSummary& s, const std::string& out_dir, bool pdf, bool quiet) {
  const fs::path d = out_dir, images = d / "images";
  fs::create_directories(images);
  render::write_text_atomic((d / "summary.json").string(), to_json(s).dump(1) + "\n");
  render::write_text_atomic((d / "summary.csv").string(), summary_csv(s));
  const auto figs = charts(s, images);
  render::write_text_atomic((d / "summary.html").string(), html(s, figs, images));
  if (!quiet) std::printf("wrote %s/summary.json, summary.csv, summary.html\n", out_dir.c_str());
  if (!pdf) return;
  std::string note;
  const std::string p = render::html_to_pdf((d / "summary.html").string(), (d / "summary.pdf").string(), &note);
  if (p.empty()) std::fprintf(stderr, "damimpact: %s\n", note.c_str());
  else if (!quiet) std::printf("wrote %s\n", p.c_str());
}

}  // namespace dmi::sweep
