#include "engine/sim/checkpoint.hpp"

#include "engine/scenario/identity.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace dmi {
namespace {
// The last character is the layout's version: raised whenever what a checkpoint holds, or its scenario fingerprint,
// changes, so that an older checkpoint is refused as such.
constexpr char kMagic[8] = {'D', 'M', 'I', 'C', 'K', 'P', 'T', 'C'};
}

std::uint64_t fnv1a(const std::string& bytes, std::uint64_t h) {
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  return h;
}

std::uint64_t scenario_fingerprint(const Scenario& s) { return std::stoull(scenario_identity(s).substr(0, 16), nullptr, 16); }

void LoopState::save(StateWriter& w) const {
  w.tag("loop");
  w.put(next_sample), w.put(next_snap), w.put(dt_min), w.put(dt_max), w.put(courant_max), w.put(j_min), w.put(wall_seconds);
  w.put(snapshots);
  for (const auto* files : {&vtk_files, &member_files}) {
    w.put<std::uint64_t>(files->size());
    for (const auto& [t, name] : *files) w.put(t), w.put(name);
  }
}

void LoopState::load(StateReader& r) {
  r.tag("loop");
  r.get(next_sample), r.get(next_snap), r.get(dt_min), r.get(dt_max), r.get(courant_max), r.get(j_min), r.get(wall_seconds);
  r.get(snapshots);
  for (auto* files : {&vtk_files, &member_files}) {
    const auto n = r.get<std::uint64_t>();
    if (n > snapshots + 1) r.fail("field-file count " + std::to_string(n) + " exceeds the snapshot count");
    files->resize(static_cast<std::size_t>(n));
    for (auto& [t, name] : *files) r.get(t), r.get(name);
  }
}

void write_checkpoint(const std::string& path, int dim, std::uint64_t fingerprint, const std::string& payload) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f) throw std::runtime_error(tmp + ": cannot create checkpoint: " + std::strerror(errno));
    const std::uint32_t d = static_cast<std::uint32_t>(dim);
    const std::uint64_t n = payload.size(), sum = fnv1a(payload);
    f.write(kMagic, sizeof kMagic);
    f.write(reinterpret_cast<const char*>(&d), sizeof d);
    f.write(reinterpret_cast<const char*>(&fingerprint), sizeof fingerprint);
    f.write(reinterpret_cast<const char*>(&n), sizeof n);
    f.write(payload.data(), static_cast<std::streamsize>(payload.size()));
    f.write(reinterpret_cast<const char*>(&sum), sizeof sum);
    f.flush();
    if (!f) {
      f.close();
      std::remove(tmp.c_str());
      throw std::runtime_error(tmp + ": cannot write checkpoint (" + std::to_string(payload.size()) + " bytes; disk full?)");
    }
  }
  std::error_code ec;
  std::filesystem::rename(tmp, path, ec);
  if (ec) throw std::runtime_error(tmp + ": cannot rename to " + path + ": " + ec.message());
}

std::string read_checkpoint(const std::string& path, int dim, std::uint64_t fingerprint) {
  std::ifstream f(path, std::ios::binary);
  if (!f) throw InputError(path + ": no checkpoint to restart from (" + std::strerror(errno) + "); run without --restart");
  std::stringstream ss;
  ss << f.rdbuf();
  const std::string all = ss.str();
  StateReader head(all, path);
  char magic[8];
  head.get(magic);
  if (std::memcmp(magic, kMagic, sizeof kMagic) != 0) head.fail("not a checkpoint of this damimpact version (bad magic); run without --restart");
  if (head.get<std::uint32_t>() != static_cast<std::uint32_t>(dim)) head.fail("written by a run of another dimension");
  if (head.get<std::uint64_t>() != fingerprint)
    head.fail("written for another scenario (the scenario file or its variant changed since); run without --restart");
  const auto n = head.get<std::uint64_t>();
  constexpr std::size_t header = sizeof kMagic + 4 + 8 + 8;
  if (n > all.size() || all.size() != header + n + 8) head.fail("truncated (" + std::to_string(all.size()) + " bytes)");
  std::string payload = all.substr(header, n);
  std::uint64_t sum;
  std::memcpy(&sum, all.data() + header + n, sizeof sum);
  if (sum != fnv1a(payload)) head.fail("checksum mismatch (the file is corrupt)");
  return payload;
}

}  // namespace dmi
