// VTK XML output (docs/results.md, "ParaView output").
// .vtu layout: UnstructuredGrid, version="1.0", header_type="UInt64", byte_order="LittleEndian",
// every DataArray format="appended". After "<AppendedData encoding="raw">" and one "_" comes,
// per array in the order declared in the header, a UInt64 byte count followed by the raw
// little-endian values; each DataArray's offset= is the position of its byte count relative to
// the first byte after "_". One VTK_VERTEX cell per particle (connectivity i, offsets i+1).
// Vectors are always written with 3 components (zero-padded below 3D). Members (write_lines_vtu): the same layout,
// one VTK_POLY_LINE cell per element (before: ASCII with 17 digits, ~7 % of a steel dam's simulate in text formatting).
// Sizes are known up front, so the header is written first and the arrays are streamed in blocks
// (no second copy of the snapshot in memory).
#include "engine/io/vtu.hpp"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <functional>
#include <limits>
#include <locale>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace dmi {

namespace {

constexpr std::uint8_t kVtkVertex = 1, kVtkPolyLine = 4;
constexpr std::size_t kBlock = 4096;  // values per streamed block

bool host_little_endian() {
  const std::uint16_t one = 1;
  unsigned char b;
  std::memcpy(&b, &one, 1);
  return b == 1;
}

// Writes n values of T to out as little-endian bytes.
template <class T> void put_le(std::ostream& out, const T* v, std::size_t n) {
  if (n == 0) return;
  if (host_little_endian()) {
    out.write(reinterpret_cast<const char*>(v), static_cast<std::streamsize>(n * sizeof(T)));
    return;
  }
  char buf[sizeof(T)];
  for (std::size_t i = 0; i < n; ++i) {
    std::memcpy(buf, &v[i], sizeof(T));
    std::reverse(buf, buf + sizeof(T));
    out.write(buf, sizeof(T));
  }
}

std::string xml_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      default: o += c;
    }
  }
  return o;
}

std::string fmt_double(double v) {
  std::ostringstream os;
  os.imbue(std::locale::classic());
  os.precision(std::numeric_limits<double>::max_digits10);
  os << v;
  return os.str();
}

// Writes path + ".tmp" through `body`, then renames it over path.
void write_atomically(const std::string& path, const std::function<void(std::ostream&)>& body) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(path + ": cannot create " + tmp);
    body(out);
    out.close();
    if (!out) {
      std::remove(tmp.c_str());
      throw std::runtime_error(path + ": cannot write " + tmp + " (disk full?)");
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(tmp.c_str());
    throw std::runtime_error(path + ": cannot rename " + tmp + ": " + why);
  }
}

// One appended DataArray: its header attributes, byte size and a function streaming its values.
struct Array {
  std::string type, name;
  int ncomp;
  std::string extra;  // further XML attributes
  std::uint64_t bytes;
  std::function<void(std::ostream&)> write;
};

template <class T> Array plain(const char* type, const char* name, int ncomp,
                               const std::vector<T>& v, std::string extra = "") {
  return {type, name, ncomp, std::move(extra), v.size() * sizeof(T), [&v](std::ostream& out) {
            put_le(out, v.data(), v.size());
          }};
}

// n points of d components (row-major) written as 3 components, zero-padded.
Array padded(const char* name, const std::vector<double>& v, std::size_t n, std::size_t d) {
  return {"Float64", name, 3, "", 3 * n * sizeof(double), [&v, n, d](std::ostream& out) {
            std::vector<double> buf;
            for (std::size_t i0 = 0; i0 < n; i0 += kBlock) {
              const std::size_t m = std::min(kBlock, n - i0);
              buf.assign(3 * m, 0.0);
              for (std::size_t i = 0; i < m; ++i)
                for (std::size_t k = 0; k < d; ++k) buf[3 * i + k] = v[d * (i0 + i) + k];
              put_le(out, buf.data(), buf.size());
            }
          }};
}

// n generated values gen(i) of type T (cell connectivity, offsets, types).
template <class T, class Gen>
Array generated(const char* type, const char* name, std::size_t n, Gen gen) {
  return {type, name, 1, "", n * sizeof(T), [n, gen](std::ostream& out) {
            std::vector<T> buf;
            for (std::size_t i0 = 0; i0 < n; i0 += kBlock) {
              buf.clear();
              for (std::size_t i = i0; i < std::min(n, i0 + kBlock); ++i) buf.push_back(gen(i));
              put_le(out, buf.data(), buf.size());
            }
          }};
}

// Writes an UnstructuredGrid of npoints and ncells with every array appended raw (the layout at the top of this
// file), the sections (PointData, CellData, Points, Cells) in the given order; field: FieldData XML or empty.
void write_appended_grid(const std::string& path, const std::string& field, std::size_t npoints, std::size_t ncells,
                         const std::vector<std::pair<std::string, std::vector<Array>>>& sections) {
  std::string head;
  head += "<?xml version=\"1.0\"?>\n";
  head +=
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\""
      " header_type=\"UInt64\">\n";
  head += "  <UnstructuredGrid>\n";
  head += field;
  head += "    <Piece NumberOfPoints=\"" + std::to_string(npoints) + "\" NumberOfCells=\"" + std::to_string(ncells) + "\">\n";
  std::uint64_t offset = 0;
  for (const auto& [tag, arrays] : sections) {
    head += "      <" + tag + ">\n";
    for (const Array& a : arrays) {
      head += "        <DataArray type=\"" + a.type + "\" Name=\"" + xml_escape(a.name) +
              "\" NumberOfComponents=\"" + std::to_string(a.ncomp) + "\"" + a.extra +
              " format=\"appended\" offset=\"" + std::to_string(offset) + "\"/>\n";
      offset += sizeof(std::uint64_t) + a.bytes;
    }
    head += "      </" + tag.substr(0, tag.find(' ')) + ">\n";
  }
  head += "    </Piece>\n";
  head += "  </UnstructuredGrid>\n";
  head += "  <AppendedData encoding=\"raw\">\n   _";

  write_atomically(path, [&](std::ostream& out) {
    out.write(head.data(), static_cast<std::streamsize>(head.size()));
    for (const auto& section : sections)
      for (const Array& a : section.second) {
        put_le(out, &a.bytes, 1);
        a.write(out);
      }
    out << "\n  </AppendedData>\n</VTKFile>\n";
  });
}

void check(const std::string& path, const char* what, std::size_t got, std::size_t want) {
  if (got != want)
    throw std::runtime_error(path + ": snapshot " + what + " has " + std::to_string(got) +
                             " values, expected " + std::to_string(want));
}

}  // namespace

void check_snapshot(const Snapshot& s, const std::string& where) {
  if (s.dim < 1 || s.dim > 3)
    throw std::runtime_error(where + ": snapshot dimension " + std::to_string(s.dim) + " not in 1..3");
  const std::size_t n = s.count, d = static_cast<std::size_t>(s.dim);
  check(where, "position", s.position.size(), n * d);
  check(where, "displacement", s.displacement.size(), n * d);
  check(where, "velocity", s.velocity.size(), n * d);
  check(where, "stress", s.stress.size(), n * 6);
  check(where, "von_mises", s.von_mises.size(), n);
  check(where, "volume", s.volume.size(), n);
  check(where, "body", s.body.size(), n);
  check(where, "material", s.material.size(), n);
}

void write_vtu(const std::string& path, const Snapshot& s) {
  check_snapshot(s, path);
  const std::size_t n = s.count, d = static_cast<std::size_t>(s.dim);

  const std::string stress_names =
      " ComponentName0=\"xx\" ComponentName1=\"yy\" ComponentName2=\"zz\""
      " ComponentName3=\"xy\" ComponentName4=\"yz\" ComponentName5=\"xz\"";
  // Sections of the Piece, in file order; the appended data follows the same order.
  const std::vector<std::pair<std::string, std::vector<Array>>> sections = {
      {"PointData Scalars=\"von_mises\" Vectors=\"velocity\"",
       {padded("displacement", s.displacement, n, d), padded("velocity", s.velocity, n, d),
        plain("Float64", "stress", 6, s.stress, stress_names),
        plain("Float64", "von_mises", 1, s.von_mises), plain("Float64", "volume", 1, s.volume),
        plain("Int32", "body", 1, s.body), plain("Int32", "material", 1, s.material)}},
      {"Points", {padded("Points", s.position, n, d)}},
      {"Cells",
       {generated<std::int64_t>("Int64", "connectivity", n,
                                [](std::size_t i) { return static_cast<std::int64_t>(i); }),
        generated<std::int64_t>("Int64", "offsets", n,
                                [](std::size_t i) { return static_cast<std::int64_t>(i + 1); }),
        generated<std::uint8_t>("UInt8", "types", n, [](std::size_t) { return kVtkVertex; })}}};

  // TimeValue/CycleIndex field data: ParaView shows the time even when a .vtu is opened alone.
  std::string field;
  field += "    <FieldData>\n";
  field += "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\"";
  field += " format=\"ascii\">" + fmt_double(s.time) + "</DataArray>\n";
  field += "      <DataArray type=\"Int64\" Name=\"CycleIndex\" NumberOfTuples=\"1\"";
  field += " format=\"ascii\">" + std::to_string(s.step) + "</DataArray>\n";
  field += "    </FieldData>\n";
  write_appended_grid(path, field, n, n, sections);
}

void write_lines_vtu(const std::string& path, const LineSnapshot& s) {
  const std::size_t d = s.dim == 3 ? 3 : 2, np = s.points.size() / d, nc = s.ends.size();
  if (s.points.size() != d * np || s.displacement.size() != d * np || (nc > 0 && s.ends.back() != np) || s.member.size() != nc)
    throw std::runtime_error(path + ": inconsistent member snapshot");
  for (const auto& [name, v] : s.point_scalars)
    if (v.size() != np) throw std::runtime_error(path + ": member field " + name + " has " + std::to_string(v.size()) + " values");
  std::vector<Array> point_data = {padded("displacement", s.displacement, np, d)};
  for (const auto& [name, v] : s.point_scalars) point_data.push_back(plain("Float64", name.c_str(), 1, v));
  const auto& ends = s.ends;
  const std::vector<std::pair<std::string, std::vector<Array>>> sections = {
      {"PointData", std::move(point_data)},
      {"CellData", {plain("Int32", "member", 1, s.member)}},
      {"Points", {padded("Points", s.points, np, d)}},
      {"Cells",
       {generated<std::int64_t>("Int64", "connectivity", np, [](std::size_t i) { return static_cast<std::int64_t>(i); }),
        generated<std::int64_t>("Int64", "offsets", nc, [&ends](std::size_t c) { return static_cast<std::int64_t>(ends[c]); }),
        generated<std::uint8_t>("UInt8", "types", nc, [](std::size_t) { return kVtkPolyLine; })}}};
  write_appended_grid(path, "", np, nc, sections);
}

void write_pvd(const std::string& path,
               const std::vector<std::pair<double, std::string>>& entries) {
  std::string text;
  text += "<?xml version=\"1.0\"?>\n";
  text += "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n";
  text += "  <Collection>\n";
  for (const auto& [time, file] : entries)
    text += "    <DataSet timestep=\"" + fmt_double(time) + "\" group=\"\" part=\"0\" file=\"" +
            xml_escape(file) + "\"/>\n";
  text += "  </Collection>\n";
  text += "</VTKFile>\n";
  write_atomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace dmi
