// results.h5 writer over the HDF5 C API. Layout (docs/results.md is the reference):
//   /                 attrs format="damimpact-results", format_version=1, complete (0 -> 1 by
//                     finish), software_version, scenario_name, scenario_file, dimension
//   /scenario         scalar string dataset: the scenario JSON text
//   /scenario_expanded scalar string: the low-level scenario of a preset file (when it has presets)
//   /documents/<name> scalar strings: JSON documents (peak_contact, solid_check)
//   /run              group; attrs = RunInfo::stats by name (double or string; engine/io/run_stats.hpp);
//                     datasets body_names, material_names (1-D string arrays)
//   /history/time     (n) double, s
//   /history/<path>   (n, ncomp) double per Series; attrs unit (string), components (1-D string
//                     array, one entry per column)
//   /snapshots/NNNN   group per snapshot (index zero-padded to at least 4 digits); attrs time
//                     (double), step (int64); datasets position, displacement, velocity
//                     (count, dim), stress (count, 6), von_mises, volume (count) double;
//                     body, material (count) int32
// All strings are fixed-length UTF-8, NUL-padded (width = longest string in that attribute or
// dataset, at least 1 byte). Datasets are uncompressed; snapshot arrays are chunked. File format:
// HDF5 1.8 (libver bounds V18), whose metadata is checksummed.
#include "engine/io/results_writer.hpp"

#include "engine/io/records_json.hpp"
#include "engine/scenario/design_basis_json.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <map>
#include <set>
#include <vector>

#include "engine/io/h5_util.hpp"

namespace dmi {

namespace {

using h5::check_id;
using h5::check_ok;
using h5::Handle;

constexpr const char* kFormatName = "damimpact-results";
constexpr std::size_t kChunkBytes = std::size_t(1) << 20;  // target chunk size for snapshot arrays

// Creates attribute `name` on loc (replacing an existing one) and writes one value.
void put_attr(hid_t loc, const std::string& name, hid_t file_type, hid_t mem_type,
              const void* value, const std::string& file) {
  const std::string what = "cannot write attribute '" + name + "'";
  const htri_t exists = H5Aexists(loc, name.c_str());
  check_ok(exists < 0 ? -1 : 0, file, what);
  if (exists > 0) check_ok(H5Adelete(loc, name.c_str()), file, what);
  Handle space(check_id(H5Screate(H5S_SCALAR), file, what), H5Sclose);
  Handle attr(check_id(H5Acreate2(loc, name.c_str(), file_type, space, H5P_DEFAULT, H5P_DEFAULT),
                       file, what),
              H5Aclose);
  check_ok(H5Awrite(attr, mem_type, value), file, what);
}

// Strings packed as one fixed-length type (width = longest string, at least 1 byte).
struct PackedStrings {
  Handle type;
  std::string bytes;  // n * width, NUL-padded
};
PackedStrings pack(const std::vector<std::string>& v, const std::string& f) {
  std::size_t width = 1;
  for (const auto& s : v) width = std::max(width, s.size());
  PackedStrings p{h5::fixed_string_type(width, f), std::string(v.size() * width, '\0')};
  for (std::size_t i = 0; i < v.size(); ++i) p.bytes.replace(i * width, v[i].size(), v[i]);
  return p;
}

void attr_string(hid_t loc, const std::string& name, const std::string& v, const std::string& f) {
  const PackedStrings p = pack({v}, f);
  put_attr(loc, name, p.type, p.type, p.bytes.data(), f);
}
void attr_int(hid_t loc, const std::string& name, int v, const std::string& f) {
  put_attr(loc, name, H5T_STD_I32LE, H5T_NATIVE_INT, &v, f);
}
void attr_int64(hid_t loc, const std::string& name, long long v, const std::string& f) {
  put_attr(loc, name, H5T_STD_I64LE, H5T_NATIVE_LLONG, &v, f);
}
void attr_double(hid_t loc, const std::string& name, double v, const std::string& f) {
  put_attr(loc, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, &v, f);
}
// 1-D string array attribute (used for Series components).
void attr_strings(hid_t loc, const std::string& name, const std::vector<std::string>& v,
                  const std::string& f) {
  const std::string what = "cannot write attribute '" + name + "'";
  const PackedStrings p = pack(v, f);
  const hsize_t dims[1] = {v.size()};
  Handle space(check_id(H5Screate_simple(1, dims, nullptr), f, what), H5Sclose);
  Handle attr(
      check_id(H5Acreate2(loc, name.c_str(), p.type, space, H5P_DEFAULT, H5P_DEFAULT), f, what),
      H5Aclose);
  if (!v.empty()) check_ok(H5Awrite(attr, p.type, p.bytes.data()), f, what);
}

// Link-creation property list that creates missing intermediate groups ("a/b/c").
Handle intermediate_lcpl(const std::string& f) {
  Handle lcpl(check_id(H5Pcreate(H5P_LINK_CREATE), f, "cannot create property list"), H5Pclose);
  check_ok(H5Pset_create_intermediate_group(lcpl, 1), f, "cannot create property list");
  return lcpl;
}

// Numeric dataset of shape dims (rank 1 or 2). Chunked (rows of ~kChunkBytes) when asked and
// non-empty; an empty dataset keeps its shape (e.g. (0, 3)) with contiguous layout.
Handle write_array(hid_t loc, const std::string& name, hid_t file_type, hid_t mem_type,
                   const void* data, const std::vector<hsize_t>& dims, bool chunked,
                   const std::string& f) {
  const std::string what = "cannot write dataset '" + name + "'";
  const int rank = static_cast<int>(dims.size());
  Handle space(check_id(H5Screate_simple(rank, dims.data(), nullptr), f, what), H5Sclose);
  Handle dcpl(check_id(H5Pcreate(H5P_DATASET_CREATE), f, what), H5Pclose);
  hsize_t total = 1;
  for (hsize_t d : dims) total *= d;
  if (chunked && total > 0) {
    std::vector<hsize_t> chunk = dims;
    const hsize_t row_bytes = (total / dims[0]) * H5Tget_size(mem_type);
    chunk[0] = std::clamp<hsize_t>(kChunkBytes / std::max<hsize_t>(row_bytes, 1), 1, dims[0]);
    check_ok(H5Pset_chunk(dcpl, rank, chunk.data()), f, what);
  }
  Handle lcpl = intermediate_lcpl(f);
  Handle ds(
      check_id(H5Dcreate2(loc, name.c_str(), file_type, space, lcpl, dcpl, H5P_DEFAULT), f, what),
      H5Dclose);
  if (total > 0) check_ok(H5Dwrite(ds, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), f, what);
  return ds;
}

void write_doubles(hid_t loc, const std::string& name, const std::vector<double>& v,
                   std::vector<hsize_t> dims, bool chunked, const std::string& f) {
  write_array(loc, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, v.data(), dims, chunked, f);
}

// String dataset: scalar (one string, /scenario) or 1-D array (body_names, material_names).
void write_strings(hid_t loc, const std::string& name, const std::vector<std::string>& v,
                   bool scalar, const std::string& f) {
  const std::string what = "cannot write dataset '" + name + "'";
  const PackedStrings p = pack(v, f);
  const hsize_t dims[1] = {v.size()};
  Handle space(
      check_id(scalar ? H5Screate(H5S_SCALAR) : H5Screate_simple(1, dims, nullptr), f, what),
      H5Sclose);
  Handle ds(
      check_id(H5Dcreate2(loc, name.c_str(), p.type, space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
               f, what),
      H5Dclose);
  if (!v.empty())
    check_ok(H5Dwrite(ds, p.type, H5S_ALL, H5S_ALL, H5P_DEFAULT, p.bytes.data()), f, what);
}

// Removes link `name` under loc if present (used when finish() rewrites what the constructor
// wrote).
void remove_link(hid_t loc, const std::string& name, const std::string& f) {
  const htri_t exists = H5Lexists(loc, name.c_str(), H5P_DEFAULT);
  check_ok(exists < 0 ? -1 : 0, f, "cannot look up '" + name + "'");
  if (exists > 0)
    check_ok(H5Ldelete(loc, name.c_str(), H5P_DEFAULT), f, "cannot replace '" + name + "'");
}

// A series path must be a relative HDF5 path of non-empty, non-dot components ("a/b/c").
bool valid_series_path(const std::string& p) {
  if (p.empty() || p == "time") return false;
  std::size_t start = 0;
  while (true) {
    const std::size_t end = p.find('/', start);
    const std::string part =
        p.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (part.empty() || part == "." || part == "..") return false;
    if (end == std::string::npos) return true;
    start = end + 1;
  }
}

void check_size(const std::string& f, const std::string& what, std::size_t got, std::size_t want) {
  if (got != want)
    throw std::runtime_error(f + ": " + what + " has " + std::to_string(got) +
                             " values, expected " + std::to_string(want));
}

// File access for writing and for reopening a partial file: STRONG close (closing the file also closes anything
// still open in it, the destructor path) and the HDF5 1.8 format, readable by any HDF5 >= 1.8, whose metadata
// (superblock, object headers, attribute heaps) carries checksums, so corruption is reported instead of parsed.
Handle file_access(const std::string& f) {
  Handle fapl(check_id(H5Pcreate(H5P_FILE_ACCESS), f, "cannot create property list"), H5Pclose);
  check_ok(H5Pset_fclose_degree(fapl, H5F_CLOSE_STRONG), f, "cannot create property list");
  check_ok(H5Pset_libver_bounds(fapl, H5F_LIBVER_V18, H5F_LIBVER_V18), f, "cannot create property list");
  return fapl;
}

}  // namespace

struct ResultsWriter::Impl {
  std::string path, partial;
  Handle file, snapshots;
  std::size_t next_snapshot = 0;
  bool finished = false;

  Impl& start(const std::string& p) {  // both constructors: the file is written as <path>.partial
    h5::silence_errors();
    path = p;
    partial = p + ".partial";
    return *this;
  }

  // Root attributes (except format/format_version/complete), /scenario and /run; replaces any
  // previous version so finish() can update what the constructor wrote.
  void write_info(const RunInfo& info) {
    const std::string& f = partial;
    attr_string(file, "software_version", info.software_version, f);
    attr_string(file, "scenario_name", info.scenario_name, f);
    attr_string(file, "scenario_file", info.scenario_file, f);
    attr_int(file, "dimension", info.dimension, f);

    remove_link(file, "scenario", f);
    write_strings(file, "scenario", {info.scenario_json}, true, f);
    remove_link(file, "scenario_expanded", f);
    if (!info.scenario_expanded_json.empty()) write_strings(file, "scenario_expanded", {info.scenario_expanded_json}, true, f);
    attr_string(file, "variant", info.variant, f);
    remove_link(file, "documents", f);
    std::map<std::string, std::string> documents = info.documents;
    if (info.peak_contact) documents["peak_contact"] = peak_contact_to_json(*info.peak_contact).dump();
    if (info.design_basis) documents["design_basis"] = design_basis_to_json(*info.design_basis).dump();
    if (info.structure) documents["structure"] = structure_to_json(*info.structure).dump();
    if (info.face_profile) documents["face_profile"] = face_profile_to_json(*info.face_profile).dump();
    if (info.solid_check) documents["solid_check"] = solid_check_to_json(*info.solid_check).dump();
    if (info.solid_field) documents["solid_field"] = solid_field_to_json(*info.solid_field).dump();
    if (!documents.empty()) {
      Handle docs(check_id(H5Gcreate2(file, "documents", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), f, "cannot create group /documents"),
                  H5Gclose);
      for (const auto& [name, text] : documents) write_strings(docs, name, {text}, true, f);
    }

    remove_link(file, "run", f);
    Handle run(check_id(H5Gcreate2(file, "run", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), f,
                        "cannot create group /run"),
               H5Gclose);
    const RunAttributes attrs = to_attributes(info.stats);
    for (const auto& [key, value] : attrs.numbers) {
      if (attrs.words.count(key) != 0)
        throw std::runtime_error(f + ": run info key '" + key + "' is both a number and a string");
      attr_double(run, key, value, f);
    }
    for (const auto& [key, value] : attrs.words) attr_string(run, key, value, f);
    write_strings(run, "body_names", info.body_names, false, f);
    write_strings(run, "material_names", info.material_names, false, f);
  }
};

ResultsWriter::ResultsWriter(const std::string& path, const RunInfo& info)
    : impl_(std::make_unique<Impl>()) {
  Impl& m = impl_->start(path);
  const std::string& f = m.partial;
  const Handle fapl = file_access(f);
  m.file = Handle(check_id(H5Fcreate(f.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl), f,
                           "cannot create results file"),
                  H5Fclose);
  attr_string(m.file, "format", kFormatName, f);
  attr_int(m.file, "format_version", kResultsFormatVersion, f);
  attr_int(m.file, "complete", 0, f);
  m.write_info(info);
  m.snapshots =
      Handle(check_id(H5Gcreate2(m.file, "snapshots", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), f,
                      "cannot create group /snapshots"),
             H5Gclose);
  check_ok(H5Fflush(m.file, H5F_SCOPE_GLOBAL), f, "cannot flush results file");
}

ResultsWriter::ResultsWriter(const std::string& path, const RunInfo& info, Resume resume) : impl_(std::make_unique<Impl>()) {
  Impl& m = impl_->start(path);
  const std::string& f = m.partial;
  const Handle fapl = file_access(f);
  m.file = Handle(check_id(H5Fopen(f.c_str(), H5F_ACC_RDWR, fapl), f, "cannot reopen the partial results of the run to restart"),
                  H5Fclose);
  m.snapshots = Handle(check_id(H5Gopen2(m.file, "snapshots", H5P_DEFAULT), f, "cannot open group /snapshots"), H5Gclose);
  H5G_info_t gi;
  check_ok(H5Gget_info(m.snapshots, &gi), f, "cannot read /snapshots");
  if (gi.nlinks < resume.snapshots)
    throw std::runtime_error(f + ": holds " + std::to_string(gi.nlinks) + " snapshots, the checkpoint expects " +
                             std::to_string(resume.snapshots));
  for (std::size_t k = resume.snapshots; k < gi.nlinks; ++k) {  // written after the checkpoint: the restart redoes them
    char name[32];
    std::snprintf(name, sizeof name, "%04zu", k);
    remove_link(m.snapshots, name, f);
  }
  m.next_snapshot = resume.snapshots;
  remove_link(m.file, "history", f);
  attr_int(m.file, "complete", 0, f);
  m.write_info(info);
  check_ok(H5Fflush(m.file, H5F_SCOPE_GLOBAL), f, "cannot flush results file");
}

ResultsWriter::~ResultsWriter() {
  if (!impl_) return;
  impl_->snapshots.close();
  impl_->file.close();  // errors ignored: the .partial stays behind as the record of the run
}

void ResultsWriter::write_snapshot(const Snapshot& s) {
  Impl& m = *impl_;
  const std::string& f = m.partial;
  if (m.finished || !m.file.valid())
    throw std::runtime_error(f + ": write_snapshot after finish()");
  check_snapshot(s, f);
  const std::size_t n = s.count, d = static_cast<std::size_t>(s.dim);

  char name[32];
  std::snprintf(name, sizeof name, "%04zu", m.next_snapshot);
  const std::string where = std::string("/snapshots/") + name;
  Handle g(check_id(H5Gcreate2(m.snapshots, name, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), f,
                    "cannot create group " + where),
           H5Gclose);
  attr_double(g, "time", s.time, f);
  attr_int64(g, "step", static_cast<long long>(s.step), f);
  const hsize_t hn = n, hd = d;
  write_doubles(g, "position", s.position, {hn, hd}, true, f);
  write_doubles(g, "displacement", s.displacement, {hn, hd}, true, f);
  write_doubles(g, "velocity", s.velocity, {hn, hd}, true, f);
  write_doubles(g, "stress", s.stress, {hn, 6}, true, f);
  write_doubles(g, "von_mises", s.von_mises, {hn}, true, f);
  write_doubles(g, "volume", s.volume, {hn}, true, f);
  write_array(g, "body", H5T_STD_I32LE, H5T_NATIVE_INT32, s.body.data(), {hn}, true, f);
  write_array(g, "material", H5T_STD_I32LE, H5T_NATIVE_INT32, s.material.data(), {hn}, true, f);
  // Flush so that a run killed later still leaves a readable .partial with this snapshot.
  check_ok(H5Fflush(m.file, H5F_SCOPE_GLOBAL), f, "cannot flush after " + where);
  ++m.next_snapshot;
}

void ResultsWriter::finish(const std::vector<double>& time, const std::vector<Series>& series,
                           const RunInfo& info) {
  close_file(time, series, info, true);
}

void ResultsWriter::abandon(const std::vector<double>& time, const std::vector<Series>& series, const RunInfo& info) {
  close_file(time, series, info, false);
}

void ResultsWriter::close_file(const std::vector<double>& time, const std::vector<Series>& series, const RunInfo& info,
                               bool complete) {
  Impl& m = *impl_;
  const std::string& f = m.partial;
  if (m.finished) throw std::runtime_error(f + ": finish() called twice");
  if (!m.file.valid()) throw std::runtime_error(f + ": finish() after the file was closed");
  // Validate everything before touching the file.
  std::set<std::string> paths;
  for (const Series& s : series) {
    if (!valid_series_path(s.path))
      throw std::runtime_error(f + ": invalid series path '" + s.path + "'");
    if (!paths.insert(s.path).second)
      throw std::runtime_error(f + ": duplicate series path '" + s.path + "'");
    if (s.components.empty())
      throw std::runtime_error(f + ": series '" + s.path + "' has no components");
    check_size(f, "series '" + s.path + "'", s.data.size(), time.size() * s.components.size());
  }

  remove_link(m.file, "history", f);
  Handle hist(check_id(H5Gcreate2(m.file, "history", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), f,
                       "cannot create group /history"),
              H5Gclose);
  const hsize_t n = time.size();
  write_doubles(hist, "time", time, {n}, false, f);
  for (const Series& s : series) {
    Handle ds = write_array(hist, s.path, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, s.data.data(),
                            {n, static_cast<hsize_t>(s.components.size())}, false, f);
    attr_string(ds, "unit", s.unit, f);
    attr_strings(ds, "components", s.components, f);
  }
  hist.close();
  m.write_info(info);
  attr_int(m.file, "complete", complete ? 1 : 0, f);

  m.snapshots.close();
  check_ok(H5Fflush(m.file, H5F_SCOPE_GLOBAL), f, "cannot flush results file");
  check_ok(m.file.close(), f, "cannot close results file");
  if (!complete) {
    m.finished = true;
    return;
  }
  // Only now does <path> appear (or an older complete file get replaced), atomically on POSIX.
  if (std::rename(m.partial.c_str(), m.path.c_str()) != 0)
    throw std::runtime_error(f + ": cannot rename to " + m.path + ": " + std::strerror(errno));
  m.finished = true;
}

}  // namespace dmi
