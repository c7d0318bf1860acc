// results.h5 reader (layout: docs/results.md, written by results_writer.cpp).
// Defensive by design: every object is checked for existence, kind (group/dataset), type class,
// rank and extent before anything is read, so a corrupt or foreign file ends in a
// std::runtime_error "<path>: <what is wrong>" rather than a crash or a huge allocation.
// Strings are accepted both variable- and fixed-length; a Series' components attribute may be a
// 1-D string array (what the writer produces) or a single comma-joined string.
#include <algorithm>
#include <cmath>
#include <string>
#include <type_traits>
#include <filesystem>
#include <vector>

#include "engine/io/h5_util.hpp"
#include "engine/io/results_writer.hpp"

#include "engine/common/json_input.hpp"
#include "engine/io/records_json.hpp"
#include "engine/scenario/design_basis_json.hpp"

namespace dmi {

namespace {

using h5::check_id;
using h5::check_ok;
using h5::Handle;

constexpr hsize_t kMaxElements = hsize_t(1) << 36;  // sanity bound on any dataset extent
constexpr hsize_t kMaxStrings = hsize_t(1) << 24;
constexpr int kMaxDepth = 32;  // /history nesting bound (guards against link cycles)

class Reader {
 public:
  explicit Reader(std::string file) : f_(std::move(file)) {}
  [[noreturn]] void error(const std::string& what) const { h5::fail(f_, what); }
  const std::string& file() const { return f_; }

  bool has_link(hid_t loc, const std::string& name) const {
    const htri_t r = H5Lexists(loc, name.c_str(), H5P_DEFAULT);
    if (r < 0) error("cannot look up '" + name + "'");
    return r > 0;
  }
  bool has_attr(hid_t loc, const std::string& name, const std::string& where) const {
    const htri_t r = H5Aexists(loc, name.c_str());
    if (r < 0) error("cannot look up attribute '" + name + "' on " + where);
    return r > 0;
  }

  // Opens child `name` of loc (shown as `where`) and checks it is of kind `want`.
  Handle open(hid_t loc, const std::string& name, const std::string& where, H5I_type_t want) const {
    const char* kind = want == H5I_GROUP ? "group" : "dataset";
    if (!has_link(loc, name)) error(std::string("missing ") + kind + " " + where);
    Handle obj(check_id(H5Oopen(loc, name.c_str(), H5P_DEFAULT), f_, "cannot open " + where),
               H5Oclose);
    if (H5Iget_type(obj) != want) error(where + " is not a " + kind);
    return obj;
  }

  // Extent of a dataset/attribute dataspace; scalar -> {} (rank 0).
  std::vector<hsize_t> extent(hid_t space, const std::string& where) const {
    const H5S_class_t cls = H5Sget_simple_extent_type(space);
    if (cls == H5S_SCALAR) return {};
    if (cls != H5S_SIMPLE) error(where + " has no data (null or invalid dataspace)");
    const int rank = H5Sget_simple_extent_ndims(space);
    if (rank < 0 || rank > 8) error(where + " has an invalid rank");
    std::vector<hsize_t> dims(static_cast<std::size_t>(rank));
    if (rank > 0 && H5Sget_simple_extent_dims(space, dims.data(), nullptr) < 0)
      error("cannot read the shape of " + where);
    hsize_t total = 1;
    for (hsize_t d : dims) {
      if (d > kMaxElements || (d > 0 && total > kMaxElements / d))
        error(where + " has an implausible size (corrupt file?)");
      total *= d;
    }
    return dims;
  }

  static std::string shape_str(const std::vector<hsize_t>& d) {
    std::string s = "(";
    for (std::size_t i = 0; i < d.size(); ++i) s += (i ? ", " : "") + std::to_string(d[i]);
    return s + ")";
  }

  // Reads a numeric dataset whose shape must equal `want`, converting to mem_type.
  template <class T> std::vector<T> read_numbers(hid_t ds, const std::string& where,
                                                 const std::vector<hsize_t>& want, hid_t mem_type,
                                                 bool integer_only) const {
    Handle type(check_id(H5Dget_type(ds), f_, "cannot read the type of " + where), H5Tclose);
    const H5T_class_t cls = H5Tget_class(type);
    if (cls != H5T_INTEGER && (integer_only || cls != H5T_FLOAT))
      error(where + (integer_only ? " is not an integer array" : " is not a numeric array"));
    Handle space(check_id(H5Dget_space(ds), f_, "cannot read the shape of " + where), H5Sclose);
    const std::vector<hsize_t> dims = extent(space, where);
    if (dims != want)
      error(where + " has shape " + shape_str(dims) + ", expected " + shape_str(want));
    hsize_t n = 1;
    for (hsize_t d : dims) n *= d;
    std::vector<T> out;
    if (n == 0) return out;
    // The stored bytes must cover the extent; otherwise the file is truncated or corrupt.
    if (H5Dget_storage_size(ds) < n * H5Tget_size(type))
      error(where + " holds less data than its shape " + shape_str(dims) +
            " (truncated or corrupt)");
    out.resize(static_cast<std::size_t>(n));
    check_ok(H5Dread(ds, mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), f_,
             "cannot read " + where);
    // Results never hold NaN or inf (a run stops at the first non-finite value): one here is damage, and read as a
    // number it would pass every check.
    if constexpr (std::is_floating_point_v<T>) {
      const auto bad = std::find_if(out.begin(), out.end(), [](T v) { return !std::isfinite(v); });
      if (bad != out.end())
        error(where + " holds a non-finite value (" + (std::isnan(*bad) ? std::string("nan") : std::string("inf")) + ") at entry " +
              std::to_string(bad - out.begin()) + " of " + std::to_string(out.size()) + "; results are never so: the file is damaged");
    }
    return out;
  }
  std::vector<double> doubles(hid_t loc, const std::string& name, const std::string& where,
                              const std::vector<hsize_t>& want) const {
    Handle ds = open(loc, name, where, H5I_DATASET);
    return read_numbers<double>(ds, where, want, H5T_NATIVE_DOUBLE, false);
  }
  std::vector<std::int32_t> int32s(hid_t loc, const std::string& name, const std::string& where,
                                   const std::vector<hsize_t>& want) const {
    Handle ds = open(loc, name, where, H5I_DATASET);
    return read_numbers<std::int32_t>(ds, where, want, H5T_NATIVE_INT32, true);
  }
  std::vector<hsize_t> dataset_extent(hid_t ds, const std::string& where) const {
    Handle space(check_id(H5Dget_space(ds), f_, "cannot read the shape of " + where), H5Sclose);
    return extent(space, where);
  }

  // All strings of a string attribute (is_attr) or dataset: scalar -> one entry, 1-D -> n.
  std::vector<std::string> strings(hid_t obj, bool is_attr, const std::string& where) const {
    Handle type(check_id(is_attr ? H5Aget_type(obj) : H5Dget_type(obj), f_,
                         "cannot read the type of " + where),
                H5Tclose);
    if (H5Tget_class(type) != H5T_STRING) error(where + " is not a string");
    Handle space(check_id(is_attr ? H5Aget_space(obj) : H5Dget_space(obj), f_,
                          "cannot read the shape of " + where),
                 H5Sclose);
    const std::vector<hsize_t> dims = extent(space, where);
    if (dims.size() > 1) error(where + " is not a string or 1-D string array");
    const hsize_t n = dims.empty() ? 1 : dims[0];
    if (n > kMaxStrings) error(where + " has an implausible size (corrupt file?)");
    std::vector<std::string> out;
    if (n == 0) return out;
    const htri_t vlen = H5Tis_variable_str(type);
    if (vlen < 0) error("cannot read the type of " + where);
    Handle mem(check_id(H5Tcopy(H5T_C_S1), f_, "cannot read " + where), H5Tclose);
    const std::size_t size = vlen ? 0 : H5Tget_size(type);
    if (!vlen && (size == 0 || size > (std::size_t(1) << 26) || n * size > (hsize_t(1) << 30)))
      error(where + " has an implausible string size (corrupt file?)");
    check_ok(H5Tset_size(mem, vlen ? H5T_VARIABLE : size), f_, "cannot read " + where);
    check_ok(H5Tset_cset(mem, H5Tget_cset(type)), f_, "cannot read " + where);
    check_ok(H5Tset_strpad(mem, H5Tget_strpad(type)), f_, "cannot read " + where);
    auto read = [&](void* buf) {
      const herr_t r =
          is_attr ? H5Aread(obj, mem, buf) : H5Dread(obj, mem, H5S_ALL, H5S_ALL, H5P_DEFAULT, buf);
      check_ok(r, f_, "cannot read " + where);
    };
    if (vlen) {
      std::vector<char*> buf(static_cast<std::size_t>(n), nullptr);
      read(buf.data());
      for (char* p : buf) {
        out.emplace_back(p ? p : "");
        if (p) H5free_memory(p);
      }
    } else {
      std::vector<char> buf(static_cast<std::size_t>(n * size));
      read(buf.data());
      const bool spacepad = H5Tget_strpad(type) == H5T_STR_SPACEPAD;
      for (hsize_t i = 0; i < n; ++i) {
        const char* p = buf.data() + i * size;
        std::string s(p, std::find(p, p + size, '\0'));
        if (spacepad) s.erase(s.find_last_not_of(' ') + 1);
        out.push_back(std::move(s));
      }
    }
    return out;
  }

  // Single-valued attributes. Missing -> error (all attributes read here are required).
  Handle attr(hid_t loc, const std::string& name, const std::string& where) const {
    if (!has_attr(loc, name, where)) error("missing attribute '" + name + "' on " + where);
    return Handle(check_id(H5Aopen(loc, name.c_str(), H5P_DEFAULT), f_,
                           "cannot open attribute '" + name + "' on " + where),
                  H5Aclose);
  }
  std::string attr_string(hid_t loc, const std::string& name, const std::string& where) const {
    Handle a = attr(loc, name, where);
    std::vector<std::string> v = strings(a, true, "attribute '" + name + "' on " + where);
    if (v.size() != 1) error("attribute '" + name + "' on " + where + " is not a single string");
    return v[0];
  }
  template <class T> T attr_number(hid_t loc, const std::string& name, const std::string& where,
                                   hid_t mem_type, bool integer_only) const {
    Handle a = attr(loc, name, where);
    const std::string what = "attribute '" + name + "' on " + where;
    Handle type(check_id(H5Aget_type(a), f_, "cannot read " + what), H5Tclose);
    const H5T_class_t cls = H5Tget_class(type);
    if (cls != H5T_INTEGER && (integer_only || cls != H5T_FLOAT))
      error(what + (integer_only ? " is not an integer" : " is not a number"));
    Handle space(check_id(H5Aget_space(a), f_, "cannot read " + what), H5Sclose);
    if (H5Sget_simple_extent_npoints(space) != 1) error(what + " is not a single value");
    T v{};
    check_ok(H5Aread(a, mem_type, &v), f_, "cannot read " + what);
    return v;
  }

  // Names of the hard links in group g (other link kinds are not part of the layout), sorted. Listed in HDF5's native
  // order and sorted here: listing in increasing name order makes HDF5 1.10 build a link table, which it frees
  // uninitialised when the group's link storage fails its checksum (an invalid free inside libhdf5 on a corrupt
  // file, found by fuzz/fuzz_results.cpp); native order walks the name index directly and returns the error.
  std::vector<std::string> children(hid_t g, const std::string& where) const {
    H5G_info_t info;
    check_ok(H5Gget_info(g, &info), f_, "cannot list " + where);
    if (info.nlinks > kMaxStrings) error(where + " has an implausible number of entries");
    std::vector<std::string> out;
    hsize_t idx = 0;
    auto collect = [](hid_t, const char* name, const H5L_info_t* li, void* data) -> herr_t {
      auto* names = static_cast<std::vector<std::string>*>(data);
      if (names->size() >= kMaxStrings) return -1;
      try {
        if (li->type == H5L_TYPE_HARD) names->emplace_back(name);
      } catch (...) {  // no exception through the C library
        return -1;
      }
      return 0;
    };
    check_ok(H5Literate(g, H5_INDEX_NAME, H5_ITER_NATIVE, &idx, collect, &out), f_, "cannot list " + where);
    std::sort(out.begin(), out.end());
    return out;
  }

 private:
  std::string f_;
};

// Every dataset below /history (except /history/time) is a Series; groups are path segments.
void collect_series(const Reader& r, hid_t g, const std::string& rel, int depth, hsize_t n,
                    std::vector<Series>& out) {
  const std::string where = "/history" + (rel.empty() ? std::string() : "/" + rel);
  if (depth > kMaxDepth) r.error(where + " is nested too deeply");
  for (const std::string& name : r.children(g, where)) {
    if (rel.empty() && name == "time") continue;
    const std::string path = rel.empty() ? name : rel + "/" + name;
    const std::string at = "/history/" + path;
    Handle obj(check_id(H5Oopen(g, name.c_str(), H5P_DEFAULT), r.file(), "cannot open " + at),
               H5Oclose);
    const H5I_type_t kind = H5Iget_type(obj);
    if (kind == H5I_GROUP) {
      collect_series(r, obj, path, depth + 1, n, out);
      continue;
    }
    if (kind != H5I_DATASET) continue;  // e.g. a committed datatype: not part of the layout
    const std::vector<hsize_t> dims = r.dataset_extent(obj, at);
    if (dims.size() != 2 || dims[0] != n || dims[1] == 0)
      r.error(at + " has shape " + Reader::shape_str(dims) + ", expected (" + std::to_string(n) +
              ", ncomp) to match /history/time");
    Series s;
    s.path = path;
    s.unit = r.attr_string(obj, "unit", at);
    Handle ca = r.attr(obj, "components", at);
    s.components = r.strings(ca, true, "attribute 'components' on " + at);
    if (s.components.size() == 1 && dims[1] > 1) {  // accepted alternative: "x,y,z"
      const std::string joined = s.components[0];
      s.components.clear();
      std::size_t start = 0, comma;
      while ((comma = joined.find(',', start)) != std::string::npos) {
        s.components.push_back(joined.substr(start, comma - start));
        start = comma + 1;
      }
      s.components.push_back(joined.substr(start));
    }
    if (s.components.size() != dims[1])
      r.error(at + " has " + std::to_string(dims[1]) + " columns but " +
              std::to_string(s.components.size()) + " component names");
    s.data = r.read_numbers<double>(obj, at, dims, H5T_NATIVE_DOUBLE, false);
    out.push_back(std::move(s));
  }
}

Snapshot read_snapshot(const Reader& r, hid_t g, const std::string& where) {
  Snapshot s;
  s.time = r.attr_number<double>(g, "time", where, H5T_NATIVE_DOUBLE, false);
  s.step = static_cast<long>(r.attr_number<long long>(g, "step", where, H5T_NATIVE_LLONG, true));
  {
    Handle pos = r.open(g, "position", where + "/position", H5I_DATASET);
    const std::vector<hsize_t> dims = r.dataset_extent(pos, where + "/position");
    if (dims.size() != 2 || dims[1] < 1 || dims[1] > 3)
      r.error(where + "/position has shape " + Reader::shape_str(dims) + ", expected (count, dim)");
    s.count = static_cast<std::size_t>(dims[0]);
    s.dim = static_cast<int>(dims[1]);
    s.position = r.read_numbers<double>(pos, where + "/position", dims, H5T_NATIVE_DOUBLE, false);
  }
  const hsize_t n = s.count, d = static_cast<hsize_t>(s.dim);
  s.displacement = r.doubles(g, "displacement", where + "/displacement", {n, d});
  s.velocity = r.doubles(g, "velocity", where + "/velocity", {n, d});
  s.stress = r.doubles(g, "stress", where + "/stress", {n, 6});
  s.von_mises = r.doubles(g, "von_mises", where + "/von_mises", {n});
  s.volume = r.doubles(g, "volume", where + "/volume", {n});
  s.body = r.int32s(g, "body", where + "/body", {n});
  s.material = r.int32s(g, "material", where + "/material", {n});
  return s;
}

// /documents: the typed records (the peak contact, the design basis: validated, InputError naming the key) and the
// other documents as their JSON text.
void read_documents(const Reader& r, hid_t file, const std::string& path, RunInfo& info) {
  if (r.has_link(file, "documents")) {
    Handle docs = r.open(file, "documents", "/documents", H5I_GROUP);
    for (const std::string& name : r.children(docs, "/documents")) {
      Handle ds = r.open(docs, name, "/documents/" + name, H5I_DATASET);
      std::vector<std::string> v = r.strings(ds, false, "/documents/" + name);
      if (v.size() != 1) r.error("/documents/" + name + " is not a single string");
      info.documents[name] = std::move(v[0]);
    }
  }
  // The typed records: a malformed one is a damaged file.
  auto typed = [&](const char* name, auto read, auto& into) {
    const auto it = info.documents.find(name);
    if (it == info.documents.end()) return;
    const std::string where = std::string("/documents/") + name;
    try {
      check_json_structure(it->second, where);
      into = read(nlohmann::json::parse(it->second, nullptr, false), where);
    } catch (const std::exception& e) {
      r.error(e.what());
    }
    info.documents.erase(it);
  };
  typed("peak_contact", peak_contact_from_json, info.peak_contact);
  typed("structure", structure_from_json, info.structure);
  typed("face_profile", face_profile_from_json, info.face_profile);
  typed("solid_check", solid_check_from_json, info.solid_check);
  typed("solid_field", solid_field_from_json, info.solid_field);
  if (const auto it = info.documents.find("design_basis"); it != info.documents.end()) {  // validated: InputError naming the key
    check_json_structure(it->second, path + ": /documents/design_basis");
    const nlohmann::json j = nlohmann::json::parse(it->second, nullptr, false);
    if (j.is_discarded()) r.error("/documents/design_basis is not valid JSON");
    info.design_basis = design_basis_from_json(j, path, "/documents/design_basis");
    info.documents.erase(it);
  }
}

// Identification first, so a foreign HDF5 file gets the clearest message.
void check_format(const Reader& r, hid_t file) {
  if (!r.has_attr(file, "format", "/"))
    r.error("not a damimpact results file (no 'format' attribute)");
  std::string format;
  try {
    format = r.attr_string(file, "format", "/");
  } catch (const std::runtime_error&) {
    r.error("not a damimpact results file ('format' attribute is not a string)");
  }
  if (format != "damimpact-results")
    r.error("not a damimpact results file (format is '" + format +
            "', expected 'damimpact-results')");
  const long long version =
      r.attr_number<long long>(file, "format_version", "/", H5T_NATIVE_LLONG, true);
  if (version != kResultsFormatVersion)
    r.error("unsupported format_version " + std::to_string(version) + " (this build reads " +
            std::to_string(kResultsFormatVersion) + ")");
}

// What the run was: the software, the scenario as given and as its presets expanded it, the variant.
void read_scenario(const Reader& r, hid_t file, RunInfo& info) {
  info.software_version = r.attr_string(file, "software_version", "/");
  info.scenario_name = r.attr_string(file, "scenario_name", "/");
  info.scenario_file = r.attr_string(file, "scenario_file", "/");
  {
    Handle ds = r.open(file, "scenario", "/scenario", H5I_DATASET);
    std::vector<std::string> v = r.strings(ds, false, "/scenario");
    if (v.size() != 1) r.error("/scenario is not a single string");
    info.scenario_json = std::move(v[0]);
  }
  if (r.has_link(file, "scenario_expanded")) {
    Handle ds = r.open(file, "scenario_expanded", "/scenario_expanded", H5I_DATASET);
    std::vector<std::string> v = r.strings(ds, false, "/scenario_expanded");
    if (v.size() != 1) r.error("/scenario_expanded is not a single string");
    info.scenario_expanded_json = std::move(v[0]);
  }
  if (r.has_attr(file, "variant", "/")) info.variant = r.attr_string(file, "variant", "/");
}

// /run: the run's numbers and words (attributes), and its bodies' and materials' names.
void read_run(const Reader& r, hid_t file, const std::string& path, RunInfo& info) {
  Handle run = r.open(file, "run", "/run", H5I_GROUP);
  std::vector<std::string> names;
  hsize_t idx = 0;
  auto collect = [](hid_t, const char* name, const H5A_info_t*, void* data) -> herr_t {
    auto* v = static_cast<std::vector<std::string>*>(data);
    if (v->size() >= kMaxStrings) return -1;
    try {
      v->emplace_back(name);
    } catch (...) {  // no exception through the C library
      return -1;
    }
    return 0;
  };
  // Native order, sorted here: as for links (children()), increasing order builds a table HDF5 1.10 mishandles.
  check_ok(H5Aiterate2(run, H5_INDEX_NAME, H5_ITER_NATIVE, &idx, collect, &names), path,
           "cannot list attributes of /run");
  std::sort(names.begin(), names.end());
  RunAttributes attrs;
  for (const std::string& name : names) {
    Handle a = r.attr(run, name, "/run");
    Handle type(check_id(H5Aget_type(a), path, "cannot read attribute '" + name + "' on /run"),
                H5Tclose);
    const H5T_class_t cls = H5Tget_class(type);
    if (cls == H5T_STRING)
      attrs.words[name] = r.attr_string(run, name, "/run");
    else if (cls == H5T_FLOAT || cls == H5T_INTEGER)
      attrs.numbers[name] = r.attr_number<double>(run, name, "/run", H5T_NATIVE_DOUBLE, false);
  }
  info.stats = from_attributes(attrs);
  Handle bn = r.open(run, "body_names", "/run/body_names", H5I_DATASET);
  info.body_names = r.strings(bn, false, "/run/body_names");
  Handle mn = r.open(run, "material_names", "/run/material_names", H5I_DATASET);
  info.material_names = r.strings(mn, false, "/run/material_names");
}

// Histories are written by finish(): required in a complete file, absent from a .partial.
void read_histories(const Reader& r, hid_t file, Results& res) {
  if (!res.complete && !r.has_link(file, "history")) return;
  Handle hist = r.open(file, "history", "/history", H5I_GROUP);
  Handle t = r.open(hist, "time", "/history/time", H5I_DATASET);
  const std::vector<hsize_t> dims = r.dataset_extent(t, "/history/time");
  if (dims.size() != 1)
    r.error("/history/time has shape " + Reader::shape_str(dims) + ", expected (n)");
  res.time = r.read_numbers<double>(t, "/history/time", dims, H5T_NATIVE_DOUBLE, false);
  collect_series(r, hist, "", 0, dims[0], res.series);
  std::sort(res.series.begin(), res.series.end(),
            [](const Series& a, const Series& b) { return a.path < b.path; });
}

void read_snapshots(const Reader& r, hid_t file, Results& res) {
  Handle snaps = r.open(file, "snapshots", "/snapshots", H5I_GROUP);
  std::vector<std::pair<unsigned long long, std::string>> order;
  for (const std::string& name : r.children(snaps, "/snapshots")) {
    const bool digits =
        !name.empty() && name.size() <= 18 &&
        std::all_of(name.begin(), name.end(), [](char c) { return c >= '0' && c <= '9'; });
    if (!digits)
      r.error("unexpected entry '/snapshots/" + name + "' (expected a snapshot index)");
    order.emplace_back(std::stoull(name), name);
  }
  std::sort(order.begin(), order.end());
  for (const auto& entry : order) {
    const std::string where = "/snapshots/" + entry.second;
    Handle g = r.open(snaps, entry.second, where, H5I_GROUP);
    res.snapshots.push_back(read_snapshot(r, g, where));
  }
  // In time order: the run writes the state at the peak contact force after the periodic snapshots around it.
  std::stable_sort(res.snapshots.begin(), res.snapshots.end(), [](const Snapshot& a, const Snapshot& b) { return a.time < b.time; });
}

Results read_file(const std::string& path, bool with_snapshots) {
  Reader r(path);
  Handle fapl(check_id(H5Pcreate(H5P_FILE_ACCESS), path, "cannot create property list"), H5Pclose);
  check_ok(H5Pset_fclose_degree(fapl, H5F_CLOSE_STRONG), path, "cannot create property list");
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, fapl), H5Fclose);
  if (!file.valid()) r.error("cannot open as HDF5 (not an HDF5 file, or truncated or corrupt)");
  check_format(r, file);
  Results res;
  res.complete = r.attr_number<long long>(file, "complete", "/", H5T_NATIVE_LLONG, true) != 0;
  res.info.dimension = static_cast<int>(r.attr_number<long long>(file, "dimension", "/", H5T_NATIVE_LLONG, true));
  read_scenario(r, file, res.info);
  read_documents(r, file, path, res.info);
  read_run(r, file, path, res.info);
  read_histories(r, file, res);
  if (with_snapshots) read_snapshots(r, file, res);
  return res;
}

}  // namespace

Results read_results(const std::string& path, bool with_snapshots) {
  h5::silence_errors();
  std::error_code ec;
  const auto status = std::filesystem::status(path, ec);
  if (!std::filesystem::exists(status)) throw std::runtime_error(path + ": file not found");
  if (!std::filesystem::is_regular_file(status))
    throw std::runtime_error(path + ": not a regular file");
  try {
    return read_file(path, with_snapshots);
  } catch (const std::runtime_error&) {
    throw;
  } catch (const std::exception& e) {  // e.g. std::bad_alloc on a corrupt extent
    throw std::runtime_error(path + ": cannot read results: " + e.what());
  }
}

}  // namespace dmi
