#include "render/report.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <csignal>
#include <optional>
#include <vector>

#include <fcntl.h>
#include <unistd.h>

#include <kainjow/mustache.hpp>

#include "render/child.hpp"
#include "render/picture_helper.hpp"

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

}  // namespace

std::string render_report_html(const json& data) {
  mu::mustache tmpl{std::string(kReportTemplate)};
  if (!tmpl.is_valid()) throw std::runtime_error("report template: " + tmpl.error_message());
  json d = data;
  d["css"] = std::string(kReportCss);
  return tmpl.render(to_data(d));
}

PdfJob::PdfJob(const std::string& pdf_path, const std::string& base) : pdf_(pdf_path) {
  const std::string wp = find_weasyprint();
  if (wp.empty()) {
    note_ = "weasyprint not found on PATH: wrote the HTML report only (install it: apt-get install weasyprint)";
    return;
  }
  std::error_code ec;
  const fs::path pdf = pdf_path, d = pdf.parent_path().empty() ? fs::path(".") : pdf.parent_path();
  const std::string stem = pdf.stem().string() + "." + std::to_string(::getpid());
  tmp_ = (d / (stem + ".pdf.tmp")).string();  // beside the PDF (renamed into place)
  std::string log = (fs::temp_directory_path(ec) / "dmi_weasyprint_XXXXXX").string();  // a name no one can foresee
  const int lfd = ::mkstemp(log.data());
  if (lfd < 0) {
    note_ = "weasyprint not started (no temporary file for its messages): wrote the HTML report only";
    return;
  }
  ::close(lfd);
  log_ = log;
  int fd[2];
  if (::pipe2(fd, O_CLOEXEC) != 0) {
    note_ = "weasyprint not started (no pipe): wrote the HTML report only";
    return;
  }
  const pid_t pid = start_child({wp, "-q", "-u", base, "-", tmp_}, fd[0], log_);  // the document on its stdin
  ::close(fd[0]);
  if (pid <= 0) {
    ::close(fd[1]);
    note_ = "weasyprint failed (cannot start " + wp + "): wrote the HTML report only";
    return;
  }
  pid_ = pid, pipe_ = fd[1];
}

PdfJob::~PdfJob() {
  if (pipe_ >= 0) ::close(pipe_);
  if (pid_ > 0) stop_child(pid_);
  std::error_code ec;
  if (!tmp_.empty()) fs::remove(tmp_, ec);
  if (!log_.empty()) fs::remove(log_, ec);
}

std::string PdfJob::finish(const std::string& html, std::string* note) {
  if (pid_ <= 0) {
    *note = note_;
    return "";
  }
  // A weasyprint that ended early closes the pipe: the write then fails (EPIPE), not the process (SIGPIPE).
  void (*old)(int) = std::signal(SIGPIPE, SIG_IGN);
  for (std::size_t at = 0; at < html.size();) {
    const ssize_t w = ::write(pipe_, html.data() + at, html.size() - at);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) break;
    at += static_cast<std::size_t>(w);
  }
  std::signal(SIGPIPE, old);
  ::close(pipe_), pipe_ = -1;
  const int status = wait_child(pid_);
  pid_ = -1;
  std::string msg;
  {
    std::ifstream in(log_);
    std::getline(in, msg);
  }
  std::error_code ec;
  fs::remove(log_, ec);
  log_.clear();
  if (status != 0 || !fs::exists(tmp_)) {
    fs::remove(tmp_, ec);
    tmp_.clear();
    *note = "weasyprint failed (" + (msg.empty() ? "exit " + std::to_string(status) : msg) + "): wrote the HTML report only";
    return "";
  }
  fs::rename(tmp_, pdf_);
  tmp_.clear();
  return pdf_;
}

std::string html_to_pdf(const std::string& html_path, const std::string& pdf_path, std::string* note) {
  std::ifstream in(html_path, std::ios::binary);
  std::stringstream text;
  if (in) text << in.rdbuf();
  if (!in || text.str().empty()) {
    *note = html_path + ": cannot read the HTML (missing or empty): no PDF";
    return "";
  }
  PdfJob job(pdf_path, html_path);
  return job.finish(text.str(), note);
}

void write_text_atomic(const std::string& path, const std::string& text) { write_atomic(path, text); }

ReportFiles report_main(const std::string& out_dir, const ReportOptions& o) {
  using clock = std::chrono::steady_clock;
  ReportFiles files;
  PictureHelper helper(out_dir, o.quantity, o.picture_processes);
  std::error_code ec;
  const fs::path d = fs::is_directory(out_dir, ec) ? fs::path(out_dir) : fs::path(out_dir).parent_path();
  design::DesignDocument design_doc;
  const std::vector<RunData> runs = load_runs(out_dir, design_doc);
  std::optional<PdfJob> pdf;  // started now: it reads the document when the pictures are done
  if (o.pdf) pdf.emplace((d / "report.pdf").string(), (d / "report.html").string());
  const fs::path images = d / "images";
  auto t0 = clock::now();
  Manifest manifest;
  try {
    manifest = render_runs(pictured_runs(runs), design_doc, images.string(), RenderOptions{o.quantity, o.quiet, 1, 0, ""}, &helper);
  } catch (const std::exception& e) {  // no pictures is not a reason to have no report
    std::fprintf(stderr, "damimpact: warning: pictures not rendered (%s); the report has no figures\n", e.what());
    manifest = Manifest{};
    manifest.error = e.what();
  }
  files.render_seconds = std::chrono::duration<double>(clock::now() - t0).count();
  t0 = clock::now();
  const json data = report_data(runs, design_doc, manifest, images.string(), o.software_version);
  files.html = (d / "report.html").string();
  const std::string html = render_report_html(data);
  write_atomic(files.html, html);
  files.html_seconds = std::chrono::duration<double>(clock::now() - t0).count();
  if (!o.quiet) std::printf("wrote %s\n", files.html.c_str());
  if (!o.pdf) return files;
  t0 = clock::now();
  files.pdf = pdf->finish(html, &files.pdf_note);
  if (files.pdf.empty()) {
    std::fprintf(stderr, "damimpact: %s\n", files.pdf_note.c_str());
    return files;
  }
  files.pdf_seconds = std::chrono::duration<double>(clock::now() - t0).count();
  if (!o.quiet) std::printf("wrote %s\n", files.pdf.c_str());
  return files;
}

}  // namespace dmi::render
