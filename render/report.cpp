#include "render/report.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

#include <kainjow/mustache.hpp>

#include "engine/common/error.hpp"

namespace dmi::render {

extern const char kReportTemplate[];  // generated from templates/ at configure time (render/CMakeLists.txt)
extern const char kReportCss[];

using nlohmann::json;
namespace fs = std::filesystem;
namespace mu = kainjow::mustache;

std::string base64(const std::string& in) {
  static const char* t = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  out.reserve((in.size() + 2) / 3 * 4);
  std::size_t i = 0;
  for (; i + 2 < in.size(); i += 3) {
    const unsigned v = (static_cast<unsigned char>(in[i]) << 16) | (static_cast<unsigned char>(in[i + 1]) << 8) | static_cast<unsigned char>(in[i + 2]);
    out += t[v >> 18], out += t[(v >> 12) & 63], out += t[(v >> 6) & 63], out += t[v & 63];
  }
  if (i + 1 == in.size()) {
    const unsigned v = static_cast<unsigned char>(in[i]) << 16;
    out += t[v >> 18], out += t[(v >> 12) & 63], out += "==";
  } else if (i + 2 == in.size()) {
    const unsigned v = (static_cast<unsigned char>(in[i]) << 16) | (static_cast<unsigned char>(in[i + 1]) << 8);
    out += t[v >> 18], out += t[(v >> 12) & 63], out += t[(v >> 6) & 63], out += '=';
  }
  return out;
}

namespace {

mu::data to_data(const json& j) {
  if (j.is_object()) {
    mu::data d{mu::data::type::object};
    for (auto it = j.begin(); it != j.end(); ++it) d.set(it.key(), to_data(it.value()));
    return d;
  }
  if (j.is_array()) {
    mu::data l{mu::data::type::list};
    for (const auto& v : j) l.push_back(to_data(v));
    return l;
  }
  if (j.is_string()) {
    if (j.get<std::string>().empty()) return mu::data{false};
    return mu::data{j.get<std::string>()};
  }
  if (j.is_boolean()) return mu::data{j.get<bool>()};
  if (j.is_null()) return mu::data{false};
  return mu::data{j.dump()};
}

void write_atomic(const fs::path& target, const std::string& text) {
  const fs::path tmp = target.string() + "." + std::to_string(::getpid()) + ".tmp";
  std::ofstream o(tmp, std::ios::binary);
  o << text;
  o.close();
  if (!o) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw std::runtime_error(target.string() + ": cannot write");
  }
  fs::rename(tmp, target);
}

// weasyprint on PATH, or "".
std::string find_weasyprint() {
  const char* path = std::getenv("PATH");
  std::stringstream ss(path ? path : "");
  std::string dir;
  while (std::getline(ss, dir, ':')) {
    const fs::path p = fs::path(dir) / "weasyprint";
    if (!dir.empty() && ::access(p.c_str(), X_OK) == 0) return p.string();
  }
  return "";
}

std::string shell_quote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}

}  // namespace

std::string render_report_html(const json& data) {
  mu::mustache tmpl{std::string(kReportTemplate)};
  if (!tmpl.is_valid()) throw std::runtime_error("report template: " + tmpl.error_message());
  json d = data;
  d["css"] = std::string(kReportCss);
  return tmpl.render(to_data(d));
}

std::string html_to_pdf(const std::string& html, const std::string& pdf_path, std::string* note) {
  const std::string wp = find_weasyprint();
  if (wp.empty()) {
    *note = "weasyprint not found on PATH: wrote the HTML report only (install it: apt-get install weasyprint)";
    return "";
  }
  std::error_code ec;
  const fs::path pdf = pdf_path, d = pdf.parent_path().empty() ? fs::path(".") : pdf.parent_path();
  const std::string stem = pdf.stem().string() + "." + std::to_string(::getpid());
  const fs::path tmp = d / (stem + ".pdf.tmp"), log = d / (stem + ".weasyprint.log");
  const std::string cmd = shell_quote(wp) + " -q " + shell_quote(html) + " " + shell_quote(tmp.string()) + " > " + shell_quote(log.string()) + " 2>&1";
  const int rc = std::system(cmd.c_str());
  std::string msg;
  {
    std::ifstream in(log);
    std::getline(in, msg);
  }
  fs::remove(log, ec);
  if (rc != 0 || !fs::exists(tmp)) {
    fs::remove(tmp, ec);
    *note = "weasyprint failed (" + (msg.empty() ? "exit " + std::to_string(rc) : msg) + "): wrote the HTML report only";
    return "";
  }
  fs::rename(tmp, pdf);
  return pdf.string();
}

void write_text_atomic(const std::string& path, const std::string& text) { write_atomic(path, text); }

ReportFiles report_main(const std::string& out_dir, const ReportOptions& o) {
  using clock = std::chrono::steady_clock;
  ReportFiles files;
  json design_doc;
  const std::vector<RunData> runs = load_runs(out_dir, design_doc);
  std::error_code ec;
  const fs::path d = fs::is_directory(out_dir, ec) ? fs::path(out_dir) : fs::path(out_dir).parent_path();
  const fs::path images = d / "images";
  auto t0 = clock::now();
  json manifest;
  try {
    manifest = render_runs(runs, design_doc, images.string(), {o.quantity, o.quiet});
  } catch (const std::exception& e) {  // no pictures is not a reason to have no report
    std::fprintf(stderr, "damimpact: warning: pictures not rendered (%s); the report has no figures\n", e.what());
    manifest = json{{"images", json::array()}, {"error", e.what()}};
  }
  files.render_seconds = std::chrono::duration<double>(clock::now() - t0).count();
  t0 = clock::now();
  const json data = report_data(runs, design_doc, manifest, images.string(), o.software_version);
  files.html = (d / "report.html").string();
  write_atomic(files.html, render_report_html(data));
  files.html_seconds = std::chrono::duration<double>(clock::now() - t0).count();
  if (!o.quiet) std::printf("wrote %s\n", files.html.c_str());
  if (!o.pdf) return files;
  t0 = clock::now();
  files.pdf = html_to_pdf(files.html, (d / "report.pdf").string(), &files.pdf_note);
  if (files.pdf.empty()) {
    std::fprintf(stderr, "damimpact: %s\n", files.pdf_note.c_str());
    return files;
  }
  files.pdf_seconds = std::chrono::duration<double>(clock::now() - t0).count();
  if (!o.quiet) std::printf("wrote %s\n", files.pdf.c_str());
  return files;
}

}  // namespace dmi::render
