// Tests of the I/O layer: results.h5 round trip, .partial/rename protocol, robust reading of bad
// files, and the VTK XML (.vtu/.pvd) writers.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <stdexcept>
#include <string>

#include "engine/io/results.hpp"
#include "engine/io/results_writer.hpp"
#include "engine/io/vtu.hpp"

namespace fs = std::filesystem;
using namespace dmi;

namespace {

class IoTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    std::random_device rd;
    dir_ = fs::temp_directory_path() / ("dmi_io_" + std::string(info->name()) + "_" +
                                        std::to_string(rd()) + std::to_string(rd()));
    fs::create_directories(dir_);
  }
  void TearDown() override {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string file(const std::string& name) const { return (dir_ / name).string(); }
  fs::path dir_;
};

std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}
void spit(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// Expects read_results(path) to throw std::runtime_error starting with the path and containing
// `what`.
void expect_read_error(const std::string& path, const std::string& what) {
  try {
    read_results(path);
    FAIL() << "no exception reading " << path;
  } catch (const std::runtime_error& e) {
    const std::string msg = e.what();
    EXPECT_EQ(msg.rfind(path, 0), 0u) << msg;
    EXPECT_NE(msg.find(what), std::string::npos) << msg;
  }
}

RunInfo make_info(int dim) {
  RunInfo info;
  info.scenario_name = "drop";
  info.scenario_file = "examples/drop.json";
  info.scenario_json = "{\"name\": \"drop\", \"note\": \"B\xC3\xA9ton \\u00e9\"}\n";
  info.software_version = "0.1.0";
  info.dimension = dim;
  info.body_names = {"block", "floor"};
  info.material_names = {"steel"};
  info.stats.cell_size = 0.01, info.stats.end_time = 1.0 / 3.0, info.stats.steps = 1234;
  info.stats.shape_function = "quadratic", info.stats.status = "running";
  info.stats.frame_periods = {0.02, 0.005};
  info.stats.profile_seconds = {{"grid_update", 0.25}, {"time_step", 1.5}};
  info.stats.other_numbers = {{"a_later_number", 7}};  // a file of a later version: kept as it is
  info.stats.other_words = {{"a_later_word", "kept"}};
  return info;
}

Snapshot make_snapshot(int dim, std::size_t count, double time, long step, double seed) {
  Snapshot s;
  s.time = time;
  s.step = step;
  s.dim = dim;
  s.count = count;
  const std::size_t n = count, d = static_cast<std::size_t>(dim);
  for (std::size_t i = 0; i < n * d; ++i) {
    s.position.push_back(seed + 0.1 * static_cast<double>(i) + 1e-17);
    s.displacement.push_back(-seed / static_cast<double>(i + 3));
    s.velocity.push_back(seed * 1e-300 * static_cast<double>(i));
  }
  for (std::size_t i = 0; i < n * 6; ++i)
    s.stress.push_back(1e9 / static_cast<double>(i + 7) - seed);
  for (std::size_t i = 0; i < n; ++i) {
    s.von_mises.push_back(2.5e8 + static_cast<double>(i) / 3.0);
    s.volume.push_back(1e-6 * (1.0 + static_cast<double>(i)));
    s.body.push_back(static_cast<std::int32_t>(i % 2));
    s.material.push_back(static_cast<std::int32_t>(-1 - static_cast<int>(i)));
  }
  return s;
}

// Writes a complete file: 5 history samples, a scalar and a 2-component series, given snapshots.
Results write_sample(const std::string& path, int dim, const std::vector<Snapshot>& snaps) {
  Results r;
  r.info = make_info(dim);
  r.complete = true;
  r.time = {0.0, 0.1, 0.2, 0.30000000000000004, 0.4};
  r.series.push_back({"energy/kinetic", "J", {"value"}, {0.0, 1.5, 2.25, 1.0 / 7.0, -0.0}});
  r.series.push_back({"walls/floor/force", "N", {"x", "y"}, {0, 1, 2, 3, 4, 5, 6, 7, 8, 9.5}});
  r.snapshots = snaps;
  ResultsWriter w(path, make_info(dim));
  for (const auto& s : snaps) w.write_snapshot(s);
  r.info.stats.status = "finished";  // finish() replaces the run info written at start
  r.info.stats.wall_seconds = 12.5;
  w.finish(r.time, r.series, r.info);
  return r;
}

void expect_same(const Snapshot& a, const Snapshot& b) {
  EXPECT_EQ(a.time, b.time);
  EXPECT_EQ(a.step, b.step);
  EXPECT_EQ(a.dim, b.dim);
  EXPECT_EQ(a.count, b.count);
  EXPECT_EQ(a.position, b.position);
  EXPECT_EQ(a.displacement, b.displacement);
  EXPECT_EQ(a.velocity, b.velocity);
  EXPECT_EQ(a.stress, b.stress);
  EXPECT_EQ(a.von_mises, b.von_mises);
  EXPECT_EQ(a.volume, b.volume);
  EXPECT_EQ(a.body, b.body);
  EXPECT_EQ(a.material, b.material);
}

void expect_same(const Results& a, const Results& b, bool snapshots) {
  EXPECT_EQ(a.complete, b.complete);
  EXPECT_EQ(a.info.scenario_name, b.info.scenario_name);
  EXPECT_EQ(a.info.scenario_file, b.info.scenario_file);
  EXPECT_EQ(a.info.scenario_json, b.info.scenario_json);
  EXPECT_EQ(a.info.software_version, b.info.software_version);
  EXPECT_EQ(a.info.dimension, b.info.dimension);
  EXPECT_EQ(a.info.body_names, b.info.body_names);
  EXPECT_EQ(a.info.material_names, b.info.material_names);
  const RunAttributes x = to_attributes(a.info.stats), y = to_attributes(b.info.stats);
  EXPECT_EQ(x.numbers, y.numbers);
  EXPECT_EQ(x.words, y.words);
  EXPECT_EQ(a.info.stats.frame_periods, b.info.stats.frame_periods);
  EXPECT_EQ(a.info.stats.profile_seconds, b.info.stats.profile_seconds);
  EXPECT_EQ(a.info.stats.wall_seconds, b.info.stats.wall_seconds);
  EXPECT_EQ(a.info.stats.status, b.info.stats.status);
  EXPECT_EQ(a.time, b.time);
  ASSERT_EQ(a.series.size(), b.series.size());
  for (std::size_t i = 0; i < a.series.size(); ++i) {
    EXPECT_EQ(a.series[i].path, b.series[i].path);
    EXPECT_EQ(a.series[i].unit, b.series[i].unit);
    EXPECT_EQ(a.series[i].components, b.series[i].components);
    EXPECT_EQ(a.series[i].data, b.series[i].data);
  }
  if (!snapshots) return;
  ASSERT_EQ(a.snapshots.size(), b.snapshots.size());
  for (std::size_t i = 0; i < a.snapshots.size(); ++i) expect_same(a.snapshots[i], b.snapshots[i]);
}

}  // namespace

TEST_F(IoTest, RoundTrip2D) {
  const std::string path = file("results.h5");
  const Results written = write_sample(
      path, 2, {make_snapshot(2, 5, 0.0, 0, 1.0), make_snapshot(2, 3, 0.5, 1000, 2.0)});
  const Results read = read_results(path);
  expect_same(written, read, true);
  ASSERT_NE(read.find("walls/floor/force"), nullptr);
  EXPECT_EQ(read.find("walls/floor/force")->samples(), 5u);

  const Results histories = read_results(path, false);
  EXPECT_TRUE(histories.snapshots.empty());
  expect_same(written, histories, false);
}

TEST_F(IoTest, RoundTrip3DAndEmptySnapshot) {
  const std::string path = file("results3d.h5");
  const Results written = write_sample(
      path, 3, {make_snapshot(3, 7, 0.25, 42, 3.0), make_snapshot(3, 0, 0.5, 84, 0.0)});
  const Results read = read_results(path);
  expect_same(written, read, true);
  ASSERT_EQ(read.snapshots.size(), 2u);
  EXPECT_EQ(read.snapshots[1].count, 0u);
  EXPECT_EQ(read.snapshots[1].dim, 3);
}

TEST_F(IoTest, PartialUntilFinish) {
  const std::string path = file("results.h5");
  ResultsWriter w(path, make_info(2));
  w.write_snapshot(make_snapshot(2, 4, 0.0, 0, 1.0));
  EXPECT_TRUE(fs::exists(path + ".partial"));
  EXPECT_FALSE(fs::exists(path));
  w.finish({0.0}, {{"dt", "s", {"value"}, {1e-5}}}, make_info(2));
  EXPECT_TRUE(fs::exists(path));
  EXPECT_FALSE(fs::exists(path + ".partial"));
  EXPECT_TRUE(read_results(path).complete);
  EXPECT_THROW(w.finish({}, {}, make_info(2)), std::runtime_error);
}

TEST_F(IoTest, DestructorWithoutFinishLeavesOnlyPartial) {
  const std::string path = file("results.h5");
  {
    ResultsWriter w(path, make_info(2));
    w.write_snapshot(make_snapshot(2, 4, 0.0, 0, 1.0));
  }
  EXPECT_FALSE(fs::exists(path));
  ASSERT_TRUE(fs::exists(path + ".partial"));
  const Results r = read_results(path + ".partial");  // still a readable, incomplete file
  EXPECT_FALSE(r.complete);
  EXPECT_TRUE(r.time.empty());
  EXPECT_TRUE(r.series.empty());
  ASSERT_EQ(r.snapshots.size(), 1u);
  expect_same(make_snapshot(2, 4, 0.0, 0, 1.0), r.snapshots[0]);
}

TEST_F(IoTest, OlderCompleteFileReplacedOnlyAtFinish) {
  const std::string path = file("results.h5");
  write_sample(path, 2, {make_snapshot(2, 2, 0.0, 0, 1.0)});
  ResultsWriter w(path, make_info(2));
  EXPECT_EQ(read_results(path).snapshots.size(), 1u);  // old file untouched while running
  w.finish({0.0, 1.0}, {}, make_info(2));
  const Results r = read_results(path);
  EXPECT_EQ(r.time.size(), 2u);
  EXPECT_TRUE(r.snapshots.empty());
}

TEST_F(IoTest, WriterRejectsInconsistentInput) {
  const std::string path = file("results.h5");
  ResultsWriter w(path, make_info(2));
  Snapshot bad = make_snapshot(2, 3, 0.0, 0, 1.0);
  bad.velocity.pop_back();
  EXPECT_THROW(w.write_snapshot(bad), std::runtime_error);
  EXPECT_THROW(w.finish({0.0, 1.0}, {{"energy/kinetic", "J", {"value"}, {1.0}}}, make_info(2)),
               std::runtime_error);
  EXPECT_THROW(w.finish({0.0}, {{"../x", "J", {"value"}, {1.0}}}, make_info(2)),
               std::runtime_error);
}

TEST_F(IoTest, MissingFileThrows) { expect_read_error(file("nope.h5"), "not found"); }

TEST_F(IoTest, TruncatedFileThrows) {
  const std::string good = file("results.h5"), cut = file("truncated.h5");
  write_sample(good, 2, {make_snapshot(2, 200, 0.0, 0, 1.0)});
  const std::string bytes = slurp(good);
  spit(cut, bytes.substr(0, bytes.size() / 2));
  expect_read_error(cut, "");
}

TEST_F(IoTest, TextFileThrows) {
  const std::string path = file("notes.h5");
  spit(path, "this is not an HDF5 file\n");
  expect_read_error(path, "HDF5");
}

// Tiny HDF5 files (HDF5 1.8 format, as the writer uses) made with the HDF5 C API, stored as hex
// so the test needs no HDF5 headers: root attributes only.
//   kOtherFormat: format = "other-results", format_version = 1
//   kVersion2:    format = "damimpact-results", format_version = 2
//   kNoScenario:  all root attributes of a valid file (complete = 1), no datasets or groups
const char* const kOtherFormat =
    "894844460d0a1a0a020808000000000000000000ffffffffffffffffda0000000000000030000000"
    "00000000bc277cdb4f48445202202645026b2645026b2645026b2645026b8f021200000000ffffff"
    "ffffffffffffffffffffffffff0a0200010000151200040000ffffffffffffffffffffffffffffff"
    "ff0c290000030007000800040000666f726d617400130100000d000000020000006f746865722d72"
    "6573756c74730c2c000003000f000c00040000666f726d61745f76657273696f6e00100800000400"
    "00000000200002000000010000005c142827";
const char* const kVersion2 =
    "894844460d0a1a0a020808000000000000000000ffffffffffffffffde0000000000000030000000"
    "00000000e4ac32924f48445202202645026b2645026b2645026b2645026b93021200000000ffffff"
    "ffffffffffffffffffffffffff0a0200010000151200040000ffffffffffffffffffffffffffffff"
    "ff0c2d0000030007000800040000666f726d61740013010000110000000200000064616d696d7061"
    "63742d726573756c74730c2c000003000f000c00040000666f726d61745f76657273696f6e001008"
    "00000400000000002000020000000200000001ddbad8";
const char* const kNoScenario =
    "894844460d0a1a0a020808000000000000000000ffffffffffffffffaf0100000000000030000000"
    "00000000e283ed434f48445202212645026b2645026b2645026b2645026b6301021200000000ffff"
    "ffffffffffffffffffffffffffff0a0200010000151200040000ffffffffffffffffffffffffffff"
    "ffff0c2d0000030007000800040000666f726d61740013010000110000000200000064616d696d70"
    "6163742d726573756c74730c2c000003000f000c00040000666f726d61745f76657273696f6e0010"
    "080000040000000000200002000000010000000c260000030009000c00040000636f6d706c657465"
    "0010080000040000000000200002000000010000000c27000003000a000c0004000064696d656e73"
    "696f6e0010080000040000000000200002000000020000000c270000030011000800040000736f66"
    "74776172655f76657273696f6e00130100000100000002000000780c24000003000e000800040000"
    "7363656e6172696f5f6e616d6500130100000100000002000000780c24000003000e000800040000"
    "7363656e6172696f5f66696c65001301000001000000020000007836ddb670";

std::string from_hex(const std::string& hex) {
  std::string bytes;
  for (std::size_t i = 0; i + 1 < hex.size(); i += 2)
    bytes.push_back(static_cast<char>(std::stoi(hex.substr(i, 2), nullptr, 16)));
  return bytes;
}

TEST_F(IoTest, WrongFormatAttributeThrows) {
  const std::string path = file("other.h5");
  spit(path, from_hex(kOtherFormat));
  expect_read_error(path, "not a damimpact results file");
}

TEST_F(IoTest, UnsupportedVersionThrows) {
  const std::string path = file("v2.h5");
  spit(path, from_hex(kVersion2));
  expect_read_error(path, "unsupported format_version 2");
}

TEST_F(IoTest, MissingDatasetThrows) {
  const std::string path = file("noscenario.h5");
  spit(path, from_hex(kNoScenario));
  expect_read_error(path, "missing dataset /scenario");
}

TEST_F(IoTest, CorruptMetadataThrows) {
  // One changed byte in the root group's object header: caught by the HDF5 1.8 format checksums.
  const std::string path = file("results.h5");
  write_sample(path, 2, {make_snapshot(2, 3, 0.0, 0, 1.0)});
  std::string bytes = slurp(path);
  const std::size_t at = bytes.find("OHDR");
  ASSERT_NE(at, std::string::npos);
  bytes[at + 6] = static_cast<char>(bytes[at + 6] ^ 0x5a);
  spit(path, bytes);
  expect_read_error(path, "");
}

TEST_F(IoTest, VtuHeaderAndSize) {
  for (int dim : {2, 3}) {
    const std::string path = file("particles_" + std::to_string(dim) + ".vtu");
    const std::size_t n = 5;
    const Snapshot s = make_snapshot(dim, n, 0.125, 7, 1.0);
    write_vtu(path, s);
    EXPECT_FALSE(fs::exists(path + ".tmp"));
    const std::string bytes = slurp(path);
    EXPECT_NE(bytes.find("NumberOfPoints=\"5\""), std::string::npos);
    EXPECT_NE(bytes.find("header_type=\"UInt64\""), std::string::npos);
    // 11 arrays, each a UInt64 byte count + data: Points/displacement/velocity 3 x f64,
    // stress 6 x f64, von_mises/volume f64, body/material i32, connectivity/offsets i64, types u8.
    const std::size_t data = 11 * 8 + n * (3 * 24 + 48 + 2 * 8 + 2 * 4 + 2 * 8 + 1);
    const std::string tail = "\n  </AppendedData>\n</VTKFile>\n";
    const std::size_t underscore = bytes.find("<AppendedData encoding=\"raw\">");
    ASSERT_NE(underscore, std::string::npos);
    const std::size_t start = bytes.find('_', underscore) + 1;
    EXPECT_EQ(bytes.size(), start + data + tail.size());
    EXPECT_EQ(bytes.substr(bytes.size() - tail.size()), tail);
    // Points: its offset= points at a byte count of n*24, then z = 0 in 2D.
    const std::size_t pts = bytes.find("Name=\"Points\"");
    const std::size_t off_at = bytes.find("offset=\"", pts) + 8;
    const std::size_t off = std::stoul(bytes.substr(off_at));
    std::uint64_t count = 0;
    std::memcpy(&count, bytes.data() + start + off, 8);
    EXPECT_EQ(count, n * 24);
    double p[3];
    std::memcpy(p, bytes.data() + start + off + 8 + 24, 24);  // second point
    EXPECT_EQ(p[0], s.position[static_cast<std::size_t>(dim)]);
    EXPECT_EQ(p[2], dim == 2 ? 0.0 : s.position[static_cast<std::size_t>(dim) + 2]);
  }
}

TEST_F(IoTest, VtuEmptySnapshot) {
  const std::string path = file("empty.vtu");
  write_vtu(path, make_snapshot(2, 0, 0.0, 0, 0.0));
  const std::string bytes = slurp(path);
  EXPECT_NE(bytes.find("NumberOfPoints=\"0\""), std::string::npos);
  Snapshot bad = make_snapshot(2, 2, 0.0, 0, 0.0);
  bad.body.clear();
  EXPECT_THROW(write_vtu(file("bad.vtu"), bad), std::runtime_error);
}

TEST_F(IoTest, PvdListsEntries) {
  const std::string path = file("particles.pvd");
  write_pvd(path, {{0.0, "particles_0000.vtu"}, {0.25, "particles_0001.vtu"}});
  const std::string text = slurp(path);
  EXPECT_NE(text.find("type=\"Collection\""), std::string::npos);
  EXPECT_NE(text.find("timestep=\"0\""), std::string::npos);
  EXPECT_NE(text.find("file=\"particles_0000.vtu\""), std::string::npos);
  EXPECT_NE(text.find("timestep=\"0.25\""), std::string::npos);
  EXPECT_NE(text.find("file=\"particles_0001.vtu\""), std::string::npos);
  EXPECT_LT(text.find("particles_0000.vtu"), text.find("particles_0001.vtu"));
}

namespace dmi {
namespace {

// The values of appended array `name` in a .vtu (every array appended raw: a UInt64 byte count, then the values).
template <class T> std::vector<T> appended(const std::string& text, const std::string& name) {
  const std::size_t tag = text.find("Name=\"" + name + "\"");
  if (tag == std::string::npos) return {};
  const std::size_t off = std::stoul(text.substr(text.find("offset=\"", tag) + 8));
  const std::size_t start = text.find('_', text.find("<AppendedData")) + 1;
  std::uint64_t bytes = 0;
  std::memcpy(&bytes, text.data() + start + off, 8);
  std::vector<T> v(bytes / sizeof(T));
  std::memcpy(v.data(), text.data() + start + off + 8, v.size() * sizeof(T));
  return v;
}

// Members as polylines: one VTK_POLY_LINE per element, point coordinates and fields as given.
TEST(MemberVtu, WritesOnePolylinePerElementWithItsFields) {
  LineSnapshot s;
  s.points = {0, 0, 0.5, 0.1, 1, 0, 1, 0, 1.5, -0.1, 2, 0};
  s.displacement.assign(12, 0.0);
  s.ends = {3, 6};
  s.member = {0, 0};
  s.point_scalars = {{"M (N m)", {1, 2, 3, 4, 5, 6}}};
  const std::string path = (std::filesystem::temp_directory_path() / ("dmi_members_" + std::to_string(::getpid()) + ".vtu")).string();
  write_lines_vtu(path, s);
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove(path);
  EXPECT_NE(text.find("NumberOfPoints=\"6\" NumberOfCells=\"2\""), std::string::npos);
  EXPECT_EQ(appended<std::int64_t>(text, "offsets"), (std::vector<std::int64_t>{3, 6}));
  EXPECT_EQ(appended<std::int64_t>(text, "connectivity"), (std::vector<std::int64_t>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(appended<std::uint8_t>(text, "types"), (std::vector<std::uint8_t>{4, 4}));  // VTK_POLY_LINE
  const std::vector<double> pts = appended<double>(text, "Points");
  ASSERT_EQ(pts.size(), 18u);  // 3 components, z = 0 in 2D
  EXPECT_EQ(pts[12], 1.5);
  EXPECT_EQ(pts[13], -0.1);
  EXPECT_EQ(pts[14], 0.0);
  EXPECT_EQ(appended<double>(text, "M (N m)"), (std::vector<double>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(appended<std::int32_t>(text, "member"), (std::vector<std::int32_t>{0, 0}));
  EXPECT_EQ(appended<double>(text, "displacement").size(), 18u);
  s.ends = {3, 5};  // does not cover the points: refused, nothing written
  EXPECT_THROW(write_lines_vtu(path, s), std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
}  // namespace dmi

// /run's attributes by name and the typed record: each known name to its field, the periods frame_period_1.. to the
// list in order (one after a gap kept as it is), profile_<phase>_seconds to the profile, others kept; and back.
TEST(RunStats, AttributesByNameAndBack) {
  RunAttributes a;
  a.numbers = {{"cell_size", 0.05},          {"steps", 10},         {"frame_period_1", 0.1}, {"frame_period_2", 0.03},
               {"frame_period_4", 0.01},     {"profile_g2p_seconds", 2}, {"courant_max", 0.4}, {"something_new", 3}};
  a.words = {{"status", "complete"}, {"notes", "cfl reduced"}, {"new_word", "x"}};
  const RunStats s = from_attributes(a);
  EXPECT_EQ(s.cell_size, 0.05);
  EXPECT_EQ(s.steps, 10);
  EXPECT_EQ(s.courant_max, 0.4);
  EXPECT_FALSE(s.wall_seconds.has_value());
  EXPECT_EQ(s.frame_periods, (std::vector<double>{0.1, 0.03}));
  EXPECT_EQ(s.other_numbers.at("frame_period_4"), 0.01);
  EXPECT_EQ(s.profile_seconds.at("g2p"), 2);
  EXPECT_EQ(s.other_numbers.at("something_new"), 3);
  EXPECT_EQ(s.status, "complete");
  EXPECT_EQ(s.notes, "cfl reduced");
  EXPECT_EQ(s.other_words.at("new_word"), "x");
  const RunAttributes b = to_attributes(s);
  EXPECT_EQ(b.numbers, a.numbers);
  EXPECT_EQ(b.words, a.words);
}
