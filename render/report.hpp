// The design report: HTML from the Mustache template templates/report.html.mustache (compiled in), filled from
// design.json, the runs' metadata and the pictures (embedded, so the HTML is self-contained); PDF from the same
// HTML with its print CSS through weasyprint, when weasyprint is installed.
#pragma once
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "core/design_basis.hpp"
#include "render/render_main.hpp"

namespace dmi::render {

struct ReportOptions {
  std::string quantity = "von_mises";
  bool quiet = false;
  bool pdf = true;
  std::string software_version;
  int picture_processes = 1;  // 2: a second process shares the pictures (RenderOptions::processes)
};

struct ReportFiles {
  std::string html, pdf;  // pdf "" when not made
  std::string pdf_note;   // why not, or ""
  double render_seconds = 0, html_seconds = 0, pdf_seconds = 0;
};

// `damimpact report OUT/`: renders the pictures (OUT/images/), writes OUT/report.html and OUT/report.pdf.
ReportFiles report_main(const std::string& out_dir, const ReportOptions& o);

// The template's data (a JSON object mirrored into Mustache data).
nlohmann::json report_data(const std::vector<RunData>& runs, const design::DesignDocument& design_doc, const Manifest& manifest,
                           const std::string& image_dir, const std::string& software_version);

// Mustache rendering of the compiled-in template with `data` (CSS inserted as "css").
std::string render_report_html(const nlohmann::json& data);
// The members' damping as the report states it: modal (scenario structure.modal_damping: its ratio and band), or
// Rayleigh C = alpha M + beta K (structure.rayleigh_damping)
// damps a mode at f by zeta(f) = alpha / (4 pi f) + pi f beta (Chopra 2012, eq. 11.4.3): the ratio at 10 Hz, 100 Hz,
// 1 kHz and 10 kHz, since it grows with frequency and a bare hard impact excites kHz modes; "none" without damping.
std::string member_damping_text(const nlohmann::json& scenario);
// An estimate's note in the report: marked when the estimate lies more than a factor of 2 from the simulated peak
// (ratio = estimate / simulated outside [0.5, 2]); a NaN ratio (not applicable) leaves the note as it is.
std::string estimate_note(double ratio, const std::string& note);
// The report's row on the boulder's model (design basis boulder.model), with the run's CFL number for a rigid one (NaN:
// not recorded); empty for a model it does not know.
std::string boulder_model_text(BoulderModel model, double cfl);

std::string base64(const std::string& bytes);

// HTML -> PDF through weasyprint, started before the document exists: it reads the HTML from a pipe, so that its
// start-up (Python and its imports, ~0.6 s here) overlaps the work that makes the document (the pictures). The PDF is
// written under a temporary name and renamed when whole.
class PdfJob {
 public:
  // Starts weasyprint for pdf_path; relative links resolve against base (the HTML file's path). Without weasyprint on
  // PATH, or when it cannot start, there is no job and finish() says why.
  PdfJob(const std::string& pdf_path, const std::string& base);
  ~PdfJob();  // a job not finished is stopped and its files removed
  PdfJob(const PdfJob&) = delete;
  PdfJob& operator=(const PdfJob&) = delete;
  // Hands over the document and waits: the PDF's path, or "" with *note saying why not (weasyprint missing or failed).
  std::string finish(const std::string& html, std::string* note);

 private:
  std::string pdf_, tmp_, log_, note_;  // log_: weasyprint's messages, in the temporary folder
  int pid_ = -1, pipe_ = -1;
};
// The same for an HTML file already written.
std::string html_to_pdf(const std::string& html_path, const std::string& pdf_path, std::string* note);
// Writes under a temporary name and renames; throws std::runtime_error naming the file.
void write_text_atomic(const std::string& path, const std::string& text);
// The report's print CSS (templates/report.css, compiled in).
extern const char kReportCss[];

}  // namespace dmi::render
