#include "engine/scenario/hydrograph_io.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "engine/common/error.hpp"
#include "engine/scenario/config.hpp"

namespace dmi {

namespace {

const char* const kColumns[] = {"time", "depth", "velocity", "density"};
const char* const kUnits[] = {"time_s", "depth_m", "velocity_m_s", "density_kg_m3"};

DVec& column(Hydrograph& h, int c) { return c == 0 ? h.time : c == 1 ? h.depth : c == 2 ? h.velocity : h.density; }

std::string trim(const std::string& s) {
  std::size_t a = 0, b = s.size();
  while (a < b && std::isspace(static_cast<unsigned char>(s[a]))) ++a;
  while (b > a && std::isspace(static_cast<unsigned char>(s[b - 1]))) --b;
  return s.substr(a, b - a);
}

std::string text(double x) {
  std::ostringstream os;
  os << x;
  return os.str();
}

// The rows' physical checks; `where(c, i)` names row i of column c for the message.
template <class Where> void check_rows(const Hydrograph& h, const Where& fail) {
  const std::size_t n = h.time.size();
  if (n < 2) fail(0, n, "at least two rows (a hydrograph is a curve in time)");
  for (std::size_t i = 0; i < n; ++i) {
    if (!(h.time[i] >= 0)) fail(0, i, "a time >= 0 s (the run starts at 0)");
    if (i > 0 && !(h.time[i] > h.time[i - 1])) fail(0, i, "times increasing row by row (previous " + text(h.time[i - 1]) + " s)");
    if (!(h.depth[i] >= 0) || !std::isfinite(h.depth[i])) fail(1, i, "a finite flow depth >= 0 m");
    if (!(h.velocity[i] >= 0) || !std::isfinite(h.velocity[i])) fail(2, i, "a finite velocity >= 0 m/s (along the bed, towards the dam)");
    if (!h.density.empty() && (!(h.density[i] > 0) || !std::isfinite(h.density[i]))) fail(3, i, "a finite density > 0 kg/m^3");
    if (!std::isfinite(h.time[i])) fail(0, i, "a finite time");
  }
  if (!(h.volume_per_width() > 0)) fail(1, n, "some flow: depth and velocity both above zero in at least one interval");
}

Hydrograph read_inline(const nlohmann::json& v, const std::string& file, const std::string& path) {
  Hydrograph h;
  h.source = "inline";
  for (auto it = v.begin(); it != v.end(); ++it)
    if (std::find_if(std::begin(kColumns), std::end(kColumns), [&](const char* c) { return it.key() == c; }) == std::end(kColumns))
      throw InputError(file, path + "/" + it.key(), "", "one of the keys time, depth, velocity, density");
  std::size_t n = 0;
  for (int c = 0; c < 4; ++c) {
    const std::string p = path + "/" + kColumns[c];
    if (!v.contains(kColumns[c])) {
      if (c == 3) continue;
      throw InputError(file, p, "", std::string("an array of ") + (c == 0 ? "times (s)" : c == 1 ? "flow depths (m)" : "velocities (m/s)"));
    }
    const nlohmann::json& a = v[kColumns[c]];
    if (!a.is_array()) throw InputError(file, p, a.dump(), "an array of numbers");
    if (c == 0) n = a.size();
    if (a.size() != n) throw InputError(file, p, "", "as many values as time (" + std::to_string(n) + "), not " + std::to_string(a.size()));
    for (std::size_t i = 0; i < a.size(); ++i) {
      if (!a[i].is_number()) throw InputError(file, p + "/" + std::to_string(i), a[i].dump(), "a number");
      column(h, c).push_back(a[i].get<double>());
    }
  }
  check_rows(h, [&](int c, std::size_t i, const std::string& what) {
    const DVec& col = column(h, c);
    const std::string p = path + "/" + kColumns[c] + (i < col.size() ? "/" + std::to_string(i) : "");
    throw InputError(file, p, i < col.size() ? text(col[i]) : "", what);
  });
  return h;
}

Hydrograph read_csv(const std::string& name, const std::string& file, const std::string& path) {
  namespace fs = std::filesystem;
  const fs::path csv = fs::path(name).is_absolute() ? fs::path(name) : fs::path(file).parent_path() / name;
  const std::string quoted = "\"" + name + "\"";
  std::ifstream in(csv);
  if (!in) throw InputError(file, path, quoted, "a readable CSV file (looked for " + csv.string() + ")");
  auto fail = [&](std::size_t line, const std::string& what) {
    throw InputError(file, path, quoted, "a CSV hydrograph; " + csv.string() + (line ? " line " + std::to_string(line) + ": " : ": ") + what);
  };
  Hydrograph h;
  h.source = name;
  int col[4] = {-1, -1, -1, -1};
  std::vector<std::size_t> row_line;
  std::string line;
  bool header = false;
  std::size_t ncols = 0;
  for (std::size_t ln = 1; std::getline(in, line); ++ln) {
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream ss(t);
    for (std::string c; std::getline(ss, c, ',');) cells.push_back(trim(c));
    if (!t.empty() && t.back() == ',') cells.push_back("");
    if (!header) {
      header = true;
      ncols = cells.size();
      for (std::size_t k = 0; k < cells.size(); ++k) {
        std::string lower = cells[k];
        for (char& ch : lower) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
        for (int c = 0; c < 4; ++c)
          if (lower == kColumns[c] || lower == kUnits[c]) {
            if (col[c] >= 0) fail(ln, std::string("the column '") + kColumns[c] + "' appears twice in the header");
            col[c] = static_cast<int>(k);
          }
      }
      for (int c = 0; c < 3; ++c)
        if (col[c] < 0)
          fail(ln, std::string("a header naming the columns time, depth, velocity and optionally density (SI units; time_s, depth_m, "
                               "velocity_m_s, density_kg_m3 also accepted); '") + kColumns[c] + "' is missing from '" + t + "'");
      continue;
    }
    if (cells.size() != ncols)
      fail(ln, std::to_string(cells.size()) + " values where the header has " + std::to_string(ncols) + " columns");
    for (int c = 0; c < 4; ++c) {
      if (col[c] < 0) continue;
      const std::string& s = cells[static_cast<std::size_t>(col[c])];
      char* end = nullptr;
      const double x = std::strtod(s.c_str(), &end);
      if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(x))
        fail(ln, std::string("column '") + kColumns[c] + "' holds '" + s + "', expected a finite number");
      column(h, c).push_back(x);
    }
    row_line.push_back(ln);
  }
  if (!header) fail(0, "a header row and at least two data rows (the file is empty)");
  check_rows(h, [&](int c, std::size_t i, const std::string& what) {
    const DVec& v = column(h, c);
    if (i < row_line.size()) fail(row_line[i], std::string("column '") + kColumns[c] + "' holds " + text(v[i]) + ", expected " + what);
    fail(0, what);
  });
  return h;
}

}  // namespace

Hydrograph read_hydrograph(const nlohmann::json& value, const std::string& file, const std::string& path) {
  if (value.is_string()) return read_csv(value.get<std::string>(), file, path);
  if (value.is_object()) return read_inline(value, file, path);
  throw InputError(file, path, value.dump().substr(0, 60),
                   "a hydrograph: the name of a CSV file (columns time, depth, velocity[, density]) or an object of arrays "
                   "{\"time\": [...], \"depth\": [...], \"velocity\": [...]}");
}

void resolve_file_references(nlohmann::json& j, const std::string& source_file) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::absolute(fs::path(source_file)).parent_path();
  auto fix = [&](nlohmann::json& v) {
    if (v.is_string() && !fs::path(v.get<std::string>()).is_absolute()) v = (dir / v.get<std::string>()).lexically_normal().string();
  };
  if (!j.is_object()) return;
  if (j.contains("debris_surge") && j["debris_surge"].is_object() && j["debris_surge"].contains("hydrograph")) fix(j["debris_surge"]["hydrograph"]);
  if (j.contains("bodies") && j["bodies"].is_array())
    for (auto& b : j["bodies"])
      if (b.is_object() && b.contains("inflow") && b["inflow"].is_object() && b["inflow"].contains("hydrograph")) fix(b["inflow"]["hydrograph"]);
}

nlohmann::json hydrograph_json(const Hydrograph& h) {
  nlohmann::json j{{"time", h.time}, {"depth", h.depth}, {"velocity", h.velocity}};
  if (!h.density.empty()) j["density"] = h.density;
  return j;
}

}  // namespace dmi
