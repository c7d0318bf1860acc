// Off-screen pictures and the report, with no DISPLAY: right size, not blank, scalar bars on the data range, every
// check in the HTML, the PDF's pages renderable, and the HTML still written without weasyprint.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>

#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>

#include "design/design.hpp"
#include "render/charts.hpp"
#include "render/field.hpp"
#include "render/frame_state.hpp"
#include "render/picture_helper.hpp"
#include "render/render_main.hpp"
#include "render/report.hpp"
#include "render/solid.hpp"
#include "engine/io/records_json.hpp"
#include "engine/scenario/sha256.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

struct Png {
  int w = 0, h = 0;
  std::size_t colours = 0;
};

Png read_png(const std::string& path) {
  auto r = vtkSmartPointer<vtkPNGReader>::New();
  r->SetFileName(path.c_str());
  r->Update();
  vtkImageData* img = r->GetOutput();
  int dims[3];
  img->GetDimensions(dims);
  auto* px = vtkUnsignedCharArray::SafeDownCast(img->GetPointData()->GetScalars());
  std::set<unsigned> seen;
  const int nc = px ? px->GetNumberOfComponents() : 0;
  for (vtkIdType i = 0; px && i < px->GetNumberOfTuples(); ++i) {
    unsigned key = 0;
    for (int c = 0; c < std::min(nc, 3); ++c) key = (key << 8) | px->GetValue(i * nc + c);
    seen.insert(key);
  }
  return {dims[0], dims[1], seen.size()};
}

int sh(const std::string& cmd) {
  const int rc = std::system(cmd.c_str());
  return WIFEXITED(rc) ? WEXITSTATUS(rc) : -1;
}

// Every word of every cell of the HTML's per-run tables (table.per-run) is in the PDF's text: a table that runs off the
// page loses its right-hand columns. Returns the number of words checked.
std::size_t per_run_words_in_pdf(const std::string& html, const std::string& pdf) {
  const std::string txt = pdf + ".txt";
  if (sh("pdftotext " + pdf + " " + txt) != 0) {
    ADD_FAILURE() << "pdftotext failed on " << pdf;
    return 0;
  }
  std::ifstream tin(txt);
  const std::string pdf_text((std::istreambuf_iterator<char>(tin)), std::istreambuf_iterator<char>());
  std::size_t words = 0;
  const std::string open = "<table class=\"grid per-run\">";
  for (std::size_t t = html.find(open); t != std::string::npos; t = html.find(open, t + 1)) {
    const std::size_t end = html.find("</table>", t);
    for (std::size_t c = html.find("<td", t); c < end; c = html.find("<td", c + 1)) {
      const std::size_t a = html.find('>', c) + 1, b = html.find("</td>", a);
      std::istringstream cell(html.substr(a, b - a));
      for (std::string w; cell >> w;)
        if (w.size() >= 2 && w.find('<') == std::string::npos && w.find('&') == std::string::npos) {
          ++words;
          EXPECT_NE(pdf_text.find(w), std::string::npos) << "'" << w << "' of the HTML's per-run tables is not in the PDF";
        }
    }
  }
  return words;
}

class Render : public ::testing::Test {
 protected:
  static fs::path dir;
  static void SetUpTestSuite() {
    unsetenv("DISPLAY");  // no X server, ever
    dir = fs::temp_directory_path() / ("dmi_render_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    const std::string scenario = std::string(DMI_SOURCE_DIR) + "/tests/data/design/cantilever_self_weight.json";
    ASSERT_EQ(sh(std::string(DMI_BINARY) + " simulate " + scenario + " -o " + dir.string() + " -q"), 0);
    ASSERT_EQ(sh(std::string(DMI_BINARY) + " check " + dir.string() + " -q"), 0);
  }
  static void TearDownTestSuite() { fs::remove_all(dir); }
};
fs::path Render::dir;

}  // namespace

TEST(RenderBasics, Sha256AndBase64KnownVectors) {
  // FIPS 180-4 examples.
  EXPECT_EQ(dmi::sha256_hex("abc"), "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  EXPECT_EQ(dmi::sha256_hex(""), "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  EXPECT_EQ(dmi::sha256_hex("abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq"),
            "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  // RFC 4648 section 10.
  EXPECT_EQ(dmi::render::base64("f"), "Zg==");
  EXPECT_EQ(dmi::render::base64("fo"), "Zm8=");
  EXPECT_EQ(dmi::render::base64("foobar"), "Zm9vYmFy");
}

TEST_F(Render, FieldPictureHasTheSizeColoursAndTheDataRangeOnItsScalarBar) {
  dmi::design::DesignDocument doc;
  const auto runs = dmi::render::load_runs(dir.string(), doc);
  ASSERT_EQ(runs.size(), 1u);
  ASSERT_TRUE(runs[0].frame.has_value());
  const std::size_t snap = runs[0].results.snapshots.size() - 1;
  dmi::render::FieldSpec spec;
  spec.width = 1200, spec.height = 700, spec.title = "test";
  for (const std::string q : {"von_mises", "sigma_yy"}) {
    spec.quantity = q;
    const fs::path png = dir / ("field_" + q + ".png");
    const auto img = dmi::render::render_field({{&runs[0].results, &*runs[0].frame, snap, "t"}}, spec, png.string());
    const Png p = read_png(png.string());
    EXPECT_EQ(p.w, 1200);
    EXPECT_EQ(p.h, 700);
    EXPECT_GT(p.colours, 100u) << q;  // text, two colour bars, members, particles: far from blank
    const auto field = dmi::render::particle_field(runs[0].results.snapshots[snap], q);
    EXPECT_DOUBLE_EQ(img.particles.lo, *std::min_element(field.begin(), field.end()));
    EXPECT_DOUBLE_EQ(img.particles.hi, *std::max_element(field.begin(), field.end()));
    // The member bar spans +- the largest fibre stress: 981 kPa at the fixed end (static cantilever).
    EXPECT_NEAR(img.members.hi, 981e3, 1.0);
    EXPECT_DOUBLE_EQ(img.members.lo, -img.members.hi);
    EXPECT_GT(img.deform_scale, 0.0);
  }
}

// One particle a hundred times hotter than the rest must not wash out the picture: the scale ends at the 99th
// percentile, and the picture reports the clipped maximum and where it is.
TEST_F(Render, RobustParticleScaleClipsAnOutlierAndStatesIt) {
  dmi::design::DesignDocument doc;
  auto runs = dmi::render::load_runs(dir.string(), doc);
  dmi::Results& r = runs[0].results;
  const std::size_t snap = r.snapshots.size() - 1;
  dmi::Snapshot& s = r.snapshots[snap];
  // 400 particles (the percentile needs more than 100 to differ from the maximum): the run's particles repeated
  // across the picture, von Mises rising from 0 to 399 kPa.
  const dmi::Snapshot one = s;
  const std::size_t n = 400;
  s.count = n;
  for (auto* v : {&s.position, &s.displacement, &s.velocity}) v->resize(n * s.dim);
  s.stress.resize(6 * n), s.von_mises.resize(n), s.volume.resize(n), s.body.resize(n), s.material.resize(n);
  for (std::size_t p = 0; p < n; ++p) {
    const std::size_t q = p % one.count;
    for (int d = 0; d < s.dim; ++d) s.position[s.dim * p + d] = one.position[one.dim * q + d] + (d == 1 ? 0.01 * static_cast<double>(p / one.count) : 0.0);
    s.von_mises[p] = 1e3 * static_cast<double>(p);
    s.volume[p] = one.volume[q], s.body[p] = one.body[q], s.material[p] = one.material[q];
  }
  const double top = *std::max_element(s.von_mises.begin(), s.von_mises.end());
  const std::size_t hot = s.count / 2;
  s.von_mises[hot] = 100 * top;
  std::vector<double> sorted(s.von_mises.begin(), s.von_mises.end());
  std::sort(sorted.begin(), sorted.end());
  const double p99 = sorted[static_cast<std::size_t>(std::ceil(0.99 * static_cast<double>(s.count))) - 1];
  dmi::render::FieldSpec spec;
  spec.width = 1000, spec.height = 600, spec.title = "outlier";
  const auto img = dmi::render::render_field({{&r, &*runs[0].frame, snap, "t"}}, spec, (dir / "outlier.png").string());
  EXPECT_DOUBLE_EQ(img.particles.hi, p99);
  EXPECT_LE(img.particles.hi, top);  // the rest of the field keeps its colours
  EXPECT_TRUE(img.clipped);
  EXPECT_DOUBLE_EQ(img.peak.value, 100 * top);
  EXPECT_DOUBLE_EQ(img.peak.at[0], s.position[s.dim * hot]);
  EXPECT_DOUBLE_EQ(img.peak.at[1], s.position[s.dim * hot + 1]);
}

// The envelope panel colours the members by the largest |fibre stress| of any history sample: the cantilever released
// under self-weight overshoots its static 981 kPa.
TEST_F(Render, MemberEnvelopeSpansEverySample) {
  dmi::design::DesignDocument doc;
  const auto runs = dmi::render::load_runs(dir.string(), doc);
  const dmi::Results& r = runs[0].results;
  const auto& f = *runs[0].frame;
  double expected = 0;
  for (std::size_t k = 0; k < r.time.size(); ++k)
    for (const auto& e : dmi::render::frame_state(r, f, k).elements)
      expected = std::max({expected, std::abs(e.top_i), std::abs(e.bottom_i), std::abs(e.top_j), std::abs(e.bottom_j)});
  const std::size_t snap = r.snapshots.size() - 1;
  const auto env = dmi::render::member_range({{&r, &f, snap, "t", true}});
  const auto at = dmi::render::member_range({{&r, &f, snap, "t"}});
  EXPECT_DOUBLE_EQ(env.hi, expected);
  EXPECT_GE(env.hi, at.hi);
  EXPECT_GT(env.hi, 981e3);
}

TEST_F(Render, ChartIsDrawnAtItsSize) {
  dmi::render::ChartSpec c;
  c.title = "sine", c.x_label = "time [ms]", c.y_label = "force [kN]", c.width = 800, c.height = 500;
  dmi::render::Curve s;
  s.label = "sin";
  for (int k = 0; k <= 100; ++k) s.x.push_back(k), s.y.push_back(std::sin(k / 10.0));
  c.curves = {s, dmi::render::limit_line("limit", 0.8, 0, 100)};
  const fs::path png = dir / "chart.png";
  c.svg_path = (dir / "chart.svg").string();
  dmi::render::render_chart(c, png.string());
  const Png p = read_png(png.string());
  EXPECT_EQ(p.w, 800);
  EXPECT_EQ(p.h, 500);
  EXPECT_GT(p.colours, 20u);
  // The vector copy: lines as polylines, the title and labels as text, no raster inside.
  std::ifstream in(c.svg_path);
  const std::string svg((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(svg.find("<svg"), std::string::npos);
  EXPECT_NE(svg.find("<polyline"), std::string::npos);
  EXPECT_NE(svg.find(">sine<"), std::string::npos);
  EXPECT_NE(svg.find(">time [ms]<"), std::string::npos);
  EXPECT_EQ(svg.find("<image"), std::string::npos);
  EXPECT_THROW(dmi::render::render_chart({"empty", "x", "y", {}, 400, 300}, (dir / "empty.png").string()), std::runtime_error);
}

// An estimate more than a factor of 2 from the simulation (the SDOF's 235 kN against 1 421 kN) is marked; within the
// factor, or not applicable, its note stays as it is.
TEST(RenderBasics, EstimatesFarFromTheSimulationAreMarked) {
  EXPECT_EQ(dmi::render::estimate_note(235.0 / 1421.0, "pulse 1.3 ms").rfind("MORE THAN A FACTOR OF 2", 0), 0u);
  EXPECT_NE(dmi::render::estimate_note(2.5, "").find("FACTOR OF 2"), std::string::npos);
  EXPECT_EQ(dmi::render::estimate_note(0.8, "pulse 1.3 ms"), "pulse 1.3 ms");
  EXPECT_EQ(dmi::render::estimate_note(NAN, "n/a"), "n/a");
}

// A field of round-off (6.3e-13 Pa, a member before the contact) gets a 1 kPa colour scale, not one that ends at its own
// round-off; a real field keeps its range.
TEST(RenderBasics, ColourScalesIgnoreRoundOff) {
  const dmi::render::Range r = dmi::render::at_least_round_off({0.0, 6.3e-13});
  EXPECT_DOUBLE_EQ(r.lo, 0.0);
  EXPECT_DOUBLE_EQ(r.hi, dmi::render::kStressScaleFloor);
  const dmi::render::Range real = dmi::render::at_least_round_off({-2e6, 17.7e6});
  EXPECT_DOUBLE_EQ(real.hi, 17.7e6);
  EXPECT_DOUBLE_EQ(dmi::render::at_least_round_off({5.0, 5.0}).hi, 5.0 + dmi::render::kStressScaleFloor);
}

// Curves of unlike magnitude: a run peaking at 0.3 against one at 25 lies flat on their common axis and is drawn again
// on its own; one at a third of the largest is not; an all-zero curve never.
TEST(RenderBasics, SmallMagnitudeCurvesGetTheirOwnPanel) {
  dmi::render::Curve bare, buffered, mid, zero;
  bare.y = {0, 25, -3}, buffered.y = {0, 0.3, 0.1}, mid.y = {0, -8.5}, zero.y = {0, 0};
  bare.label = "bare", buffered.label = "buffered";
  const auto small = dmi::render::small_magnitude_curves({bare, buffered, mid, zero});
  ASSERT_EQ(small.size(), 1u);
  EXPECT_EQ(small[0].label, "buffered");
  EXPECT_TRUE(dmi::render::small_magnitude_curves({bare, mid}).empty());
}

// The damping row: zeta(f) = alpha / (4 pi f) + pi f beta by hand for the demo dam's preset coefficients.
TEST(RenderBasics, MemberDampingStatesTheRatioAcrossFrequencies) {
  const json s{{"structure", {{"rayleigh_damping", {{"mass", 22.95}, {"stiffness", 5.17e-5}}}}}};
  // 10 Hz: 0.18263 + 0.00162 = 18.4 %; 100 Hz: 0.01826 + 0.01624 = 3.45 %; 1 kHz: 0.00183 + 0.16242 = 16.4 %; 10 kHz: 162 %.
  const std::string t = dmi::render::member_damping_text(s);
  EXPECT_NE(t.find("= 18.4 / 3.45 / 16.4 / 162 %"), std::string::npos) << t;
  EXPECT_EQ(dmi::render::member_damping_text(json{{"structure", json::object()}}), "none");
}

// The rigid boulder's row states the step the run took (its CFL number read from the results), not a number of its own.
TEST(RenderBasics, RigidBoulderRowStatesTheRunsCfl) {
  EXPECT_NE(dmi::render::boulder_model_text(dmi::BoulderModel::rigid, 0.25).find("the step is the buffer's, at CFL 0.25"), std::string::npos);
  EXPECT_NE(dmi::render::boulder_model_text(dmi::BoulderModel::rigid, 0.125).find("at CFL 0.125"), std::string::npos);
  EXPECT_EQ(dmi::render::boulder_model_text(dmi::BoulderModel::rigid, NAN).find("CFL"), std::string::npos);
  EXPECT_NE(dmi::render::boulder_model_text(dmi::BoulderModel::elastic, 0.25).find("elastic"), std::string::npos);
}

TEST_F(Render, ReportHoldsEveryCheckAndItsPdfPagesRender) {
  const auto files = dmi::render::report_main(dir.string(), {"von_mises", true, true, "test"});
  std::ifstream in(files.html);
  const std::string html((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ifstream dj(dir / "design.json");
  const json design = json::parse(dj);
  std::size_t rows = 0;
  for (std::size_t k = html.find("data-check-id="); k != std::string::npos; k = html.find("data-check-id=", k + 1)) ++rows;
  ASSERT_EQ(rows, design["runs"][0]["checks"].size());
  for (const auto& c : design["runs"][0]["checks"])
    EXPECT_NE(html.find("data-check-id=\"" + c["id"].get<std::string>() + "\""), std::string::npos) << c["id"];
  EXPECT_NE(html.find("data:image/png;base64,"), std::string::npos);  // self-contained
  EXPECT_NE(html.find("data:image/svg+xml;base64,"), std::string::npos);  // charts as vector graphics
  EXPECT_EQ(html.find("src=\"images/"), std::string::npos);
  if (files.pdf.empty()) GTEST_SKIP() << files.pdf_note;  // weasyprint is optional
  // pdftoppm renders every page; the report has at least the cover, the checks, figures, cross-checks.
  const fs::path pages = dir / "pages";
  fs::create_directories(pages);
  ASSERT_EQ(sh("pdftoppm -r 20 -png " + files.pdf + " " + (pages / "p").string()), 0);
  std::size_t n = 0;
  for (const auto& e : fs::directory_iterator(pages)) n += e.path().extension() == ".png";
  EXPECT_GE(n, 4u);
  EXPECT_LE(n, 20u);
  // The per-run tables fit the page (per_run_words).
  EXPECT_GT(per_run_words_in_pdf(html, files.pdf), 20u);
}

// Four runs side by side (a comparison with its 3D models) and a long shared text (the modal damping row): the per-run
// tables still fit the page.
TEST_F(Render, FourRunsFitThePage) {
  const fs::path four = dir.string() + "_four";
  fs::remove_all(four);
  std::ifstream in(std::string(DMI_SOURCE_DIR) + "/tests/data/design/cantilever_self_weight.json");
  json j = json::parse(in);
  j["structure"]["integrator"] = "newmark";
  j["structure"]["modal_damping"] = {{"ratio", 0.05}};
  fs::create_directories(four);
  const std::string scen = (four / "s.json").string();
  std::ofstream(scen) << j.dump();
  for (const char* v : {"with_buffer", "without_buffer", "with_buffer_3d", "without_buffer_3d"})
    ASSERT_EQ(sh(std::string(DMI_BINARY) + " simulate " + scen + " -o " + (four / v).string() + " -q"), 0);
  ASSERT_LE(sh(std::string(DMI_BINARY) + " check " + four.string() + " -q > /dev/null"), 1);
  const auto files = dmi::render::report_main(four.string(), {"von_mises", true, true, "test"});
  std::ifstream h(files.html);
  const std::string html((std::istreambuf_iterator<char>(h)), std::istreambuf_iterator<char>());
  EXPECT_NE(html.find("with buffer (3D)"), std::string::npos);
  if (files.pdf.empty()) GTEST_SKIP() << files.pdf_note;
  EXPECT_GT(per_run_words_in_pdf(html, files.pdf), 40u);
  fs::remove_all(four);
}

// Every picture, drawn by this process alone, by the second picture process alone (render --helper-of PID --claims
// DIR) or shared between the two, is the same file bit for bit, and the manifest is the same; a helper that claims
// pictures and then fails leaves them to this process; nothing of the sharing is left behind.
TEST_F(Render, PicturesSharedWithASecondProcessAreTheOnesOneProcessDraws) {
  const fs::path images = dir / "images";
  auto files = [&](const json& m) {
    std::map<std::string, std::string> bytes;
    for (const auto& e : m["images"]) {
      std::ifstream in(images / e["file"].get<std::string>(), std::ios::binary);
      std::stringstream ss;
      ss << in.rdbuf();
      bytes[e["file"]] = ss.str();
    }
    return bytes;
  };
  auto without_timing = [](json m) {
    m.erase("render_seconds"), m.erase("processes");
    return m;
  };
  auto leftovers = [&] {
    std::vector<std::string> l;
    for (const auto& e : fs::directory_iterator(images))
      if (e.path().filename().string().find(".tmp") != std::string::npos) l.push_back(e.path().filename().string());
    return l;
  };
  dmi::render::set_picture_program("");
  fs::remove_all(images);
  const json alone = dmi::render::render_main(dir.string(), {"von_mises", true, 2, 0, ""});
  EXPECT_EQ(alone["processes"], 1);  // no program set: no helper
  const auto one = files(alone);
  ASSERT_GE(one.size(), 3u);
  for (const auto& [f, b] : one) EXPECT_GT(b.size(), 1000u) << f;
  // The helper's own drawing: with no claim taken before it, every picture; no manifest.
  const fs::path claims = dir / "claims";
  fs::create_directories(claims);
  fs::remove_all(images);
  ASSERT_EQ(sh(std::string(DMI_BINARY) + " render --helper-of " + std::to_string(::getpid()) + " --claims " + claims.string() + " -q -- " + dir.string()), 0);
  EXPECT_FALSE(fs::exists(images / "images.json"));
  EXPECT_TRUE(files(alone) == one);
  EXPECT_EQ(sh(std::string(DMI_BINARY) + " render --helper-of 1 -q " + dir.string() + " 2>/dev/null"), 2);  // --claims missing
  if (dmi::render::usable_cpus() < 2) GTEST_SKIP() << "one CPU: no second process";
  dmi::render::set_picture_program(DMI_BINARY);
  fs::remove_all(images);
  const json shared = dmi::render::render_main(dir.string(), {"von_mises", true, 2, 0, ""});
  EXPECT_EQ(shared["processes"], 2);
  EXPECT_EQ(without_timing(shared), without_timing(alone));
  EXPECT_TRUE(files(shared) == one);
  EXPECT_TRUE(leftovers().empty());
  // A helper that claims the first three pictures and fails: this process draws everything.
  const fs::path fake = dir / "fake_helper.sh";
  std::ofstream(fake) << "#!/bin/sh\nwhile [ $# -gt 0 ]; do [ \"$1\" = --claims ] && touch \"$2/0\" \"$2/1\" \"$2/2\"; shift; done\nexit 1\n";
  fs::permissions(fake, fs::perms::owner_all);
  dmi::render::set_picture_program(fake.string());
  fs::remove_all(images);
  const json fallback = dmi::render::render_main(dir.string(), {"von_mises", true, 2, 0, ""});
  dmi::render::set_picture_program("");
  EXPECT_EQ(fallback["processes"], 1);
  EXPECT_EQ(without_timing(fallback), without_timing(alone));
  EXPECT_TRUE(files(fallback) == one);
  EXPECT_TRUE(leftovers().empty());
}

TEST_F(Render, WithoutWeasyprintTheHtmlIsStillWritten) {
  const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
  setenv("PATH", "/nonexistent", 1);
  const auto files = dmi::render::report_main(dir.string(), {"von_mises", true, true, "test"});
  setenv("PATH", path.c_str(), 1);
  EXPECT_TRUE(fs::exists(files.html));
  EXPECT_TRUE(files.pdf.empty());
  EXPECT_NE(files.pdf_note.find("weasyprint not found"), std::string::npos) << files.pdf_note;
}

// The solid-FE body picture of Lin, Cheng & Tuan's Table 1 model: drawn at its size, its stated peaks those of the
// field document and, to its 6 digits, of the check's own nodal peaks; a damaged field is refused with its key.
TEST(RenderSolid, TableOnePictureStatesThePeaksOfTheCheck) {
  unsetenv("DISPLAY");
  const fs::path d = fs::temp_directory_path() / ("dmi_solid_" + std::to_string(::getpid()));
  fs::remove_all(d);
  ASSERT_EQ(sh(std::string(DMI_BINARY) + " simulate " + DMI_SOURCE_DIR + "/examples/paper_b_table1.json -o " + d.string() + " -q"), 0);
  dmi::design::DesignDocument doc;
  auto runs = dmi::render::load_runs(d.string(), doc);
  ASSERT_EQ(runs.size(), 1u);
  const auto pic = dmi::render::render_solid(runs[0].results, "table 1", (d / "solid.png").string(), 1200, 600);
  ASSERT_TRUE(pic.has_value());
  const Png p = read_png((d / "solid.png").string());
  EXPECT_EQ(p.w, 1200);
  EXPECT_EQ(p.h, 600);
  EXPECT_GT(p.colours, 100u);
  // The case drawn is the one of largest nodal principal tension; its peaks agree with the solid check record.
  ASSERT_TRUE(runs[0].results.info.solid_check);
  double best = -1, vm = 0;
  std::string name;
  for (const auto& c : runs[0].results.info.solid_check->cases) {
    const double s1 = c.peaks.at("max_principal").at("node").value_Pa;
    if (s1 > best) best = s1, vm = c.peaks.at("von_mises").at("node").value_Pa, name = c.name;
  }
  EXPECT_EQ(pic->case_name, name);
  EXPECT_NEAR(pic->principal_max / best, 1.0, 1e-5);  // the field holds 6 significant digits
  EXPECT_NEAR(pic->von_mises_max / vm, 1.0, 1e-5);
  EXPECT_NEAR(pic->section_y, 1.0, 1e-9);  // the 2 m face's middle
  // A non-finite stress (written as null) is refused when the file is read, naming the document: never a picture.
  json field = dmi::solid_field_to_json(*runs[0].results.info.solid_field);
  field["cases"][0]["von_mises_Pa"][5] = nullptr;
  try {
    dmi::solid_field_from_json(field, "/documents/solid_field");
    ADD_FAILURE() << "a damaged field was read";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/documents/solid_field is malformed"), std::string::npos) << e.what();
  }
  runs[0].results.info.solid_field.reset();
  EXPECT_FALSE(dmi::render::render_solid(runs[0].results, "none", (d / "none.png").string()).has_value());
  fs::remove_all(d);
}
