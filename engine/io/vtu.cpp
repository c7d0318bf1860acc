// VTK XML output (docs/results.md, "ParaView output").
// .vtu layout: UnstructuredGrid, version="1.0", header_type="UInt64", byte_order="LittleEndian",
// every DataArray format="appended". After "<AppendedData encoding="raw">" and one "_" comes,
// per array in the order declared in the header, a UInt64 byte count followed by the raw
// little-endian values; each DataArray's offset= is the position of its byte count relative to
// the first byte after "_". One VTK_VERTEX cell per particle (connectivity i, offsets i+1).
// Vectors are always written with 3 components (zero-padded below 3D).
#include "engine/io/vtu.hpp"

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <limits>
#include <locale>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace dmi {

namespace {

constexpr std::uint8_t kVtkVertex = 1;

bool host_little_endian() {
  const std::uint16_t one = 1;
  unsigned char b;
  std::memcpy(&b, &one, 1);
  return b == 1;
}

// Appends n values of T to out as little-endian bytes.
template <class T> void put_le(std::string& out, const T* v, std::size_t n) {
  const std::size_t start = out.size();
  out.resize(start + n * sizeof(T));
  if (n == 0) return;
  std::memcpy(&out[start], v, n * sizeof(T));
  if (!host_little_endian())
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t a = 0, b = sizeof(T) - 1; a < b; ++a, --b)
        std::swap(out[start + i * sizeof(T) + a], out[start + i * sizeof(T) + b]);
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

// Writes text to path + ".tmp", then renames it over path.
void write_atomically(const std::string& path, const std::string& head, const std::string& body,
                      const std::string& tail) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    if (!out) throw std::runtime_error(path + ": cannot create " + tmp);
    out.write(head.data(), static_cast<std::streamsize>(head.size()));
    out.write(body.data(), static_cast<std::streamsize>(body.size()));
    out.write(tail.data(), static_cast<std::streamsize>(tail.size()));
    out.close();
    if (!out) {
      std::remove(tmp.c_str());
      throw std::runtime_error(path + ": write failed (disk full?)");
    }
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) {
    const std::string why = std::strerror(errno);
    std::remove(tmp.c_str());
    throw std::runtime_error(path + ": cannot rename " + tmp + ": " + why);
  }
}

// Collects the appended-data block and the matching DataArray header lines.
class Appended {
 public:
  template <class T> std::string array(const char* vtk_type, const std::string& name, int ncomp,
                                       const std::vector<T>& v, const std::string& extra = "") {
    std::string line = "<DataArray type=\"" + std::string(vtk_type) + "\" Name=\"" + name +
                       "\" NumberOfComponents=\"" + std::to_string(ncomp) + "\"" + extra +
                       " format=\"appended\" offset=\"" + std::to_string(data_.size()) + "\"/>\n";
    const std::uint64_t bytes = v.size() * sizeof(T);
    put_le(data_, &bytes, 1);
    put_le(data_, v.data(), v.size());
    return line;
  }
  const std::string& data() const { return data_; }

 private:
  std::string data_;
};

void check(const std::string& path, const char* what, std::size_t got, std::size_t want) {
  if (got != want)
    throw std::runtime_error(path + ": snapshot " + what + " has " + std::to_string(got) +
                             " values, expected " + std::to_string(want));
}

}  // namespace

void write_vtu(const std::string& path, const Snapshot& s) {
  if (s.dim < 1 || s.dim > 3)
    throw std::runtime_error(path + ": snapshot dimension " + std::to_string(s.dim) +
                             " not in 1..3");
  const std::size_t n = s.count, d = static_cast<std::size_t>(s.dim);
  check(path, "position", s.position.size(), n * d);
  check(path, "displacement", s.displacement.size(), n * d);
  check(path, "velocity", s.velocity.size(), n * d);
  check(path, "stress", s.stress.size(), n * 6);
  check(path, "von_mises", s.von_mises.size(), n);
  check(path, "volume", s.volume.size(), n);
  check(path, "body", s.body.size(), n);
  check(path, "material", s.material.size(), n);

  auto pad3 = [&](const std::vector<double>& v) {
    std::vector<double> o(3 * n, 0.0);
    for (std::size_t i = 0; i < n; ++i)
      for (std::size_t k = 0; k < d; ++k) o[3 * i + k] = v[d * i + k];
    return o;
  };
  std::vector<std::int64_t> conn(n), offsets(n);
  for (std::size_t i = 0; i < n; ++i) {
    conn[i] = static_cast<std::int64_t>(i);
    offsets[i] = static_cast<std::int64_t>(i + 1);
  }
  const std::vector<std::uint8_t> types(n, kVtkVertex);
  const std::string stress_names =
      " ComponentName0=\"xx\" ComponentName1=\"yy\" ComponentName2=\"zz\""
      " ComponentName3=\"xy\" ComponentName4=\"yz\" ComponentName5=\"xz\"";

  // Arrays are appended in the order their header lines appear below.
  Appended app;
  const std::string pd = "        ";
  std::string point_data;
  point_data += pd + app.array("Float64", "displacement", 3, pad3(s.displacement));
  point_data += pd + app.array("Float64", "velocity", 3, pad3(s.velocity));
  point_data += pd + app.array("Float64", "stress", 6, s.stress, stress_names);
  point_data += pd + app.array("Float64", "von_mises", 1, s.von_mises);
  point_data += pd + app.array("Float64", "volume", 1, s.volume);
  point_data += pd + app.array("Int32", "body", 1, s.body);
  point_data += pd + app.array("Int32", "material", 1, s.material);
  const std::string points = pd + app.array("Float64", "Points", 3, pad3(s.position));
  std::string cells = pd + app.array("Int64", "connectivity", 1, conn);
  cells += pd + app.array("Int64", "offsets", 1, offsets);
  cells += pd + app.array("UInt8", "types", 1, types);

  const std::string np = std::to_string(n);
  std::string head;
  head += "<?xml version=\"1.0\"?>\n";
  head +=
      "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\""
      " header_type=\"UInt64\">\n";
  head += "  <UnstructuredGrid>\n";
  // TimeValue/CycleIndex field data: ParaView shows the time even when a .vtu is opened alone.
  head += "    <FieldData>\n";
  head +=
      "      <DataArray type=\"Float64\" Name=\"TimeValue\" NumberOfTuples=\"1\" "
      "format=\"ascii\">" +
      fmt_double(s.time) + "</DataArray>\n";
  head +=
      "      <DataArray type=\"Int64\" Name=\"CycleIndex\" NumberOfTuples=\"1\" format=\"ascii\">" +
      std::to_string(s.step) + "</DataArray>\n";
  head += "    </FieldData>\n";
  head += "    <Piece NumberOfPoints=\"" + np + "\" NumberOfCells=\"" + np + "\">\n";
  head += "      <PointData Scalars=\"von_mises\" Vectors=\"velocity\">\n" + point_data;
  head += "      </PointData>\n";
  head += "      <Points>\n" + points + "      </Points>\n";
  head += "      <Cells>\n" + cells + "      </Cells>\n";
  head += "    </Piece>\n";
  head += "  </UnstructuredGrid>\n";
  head += "  <AppendedData encoding=\"raw\">\n   _";
  write_atomically(path, head, app.data(), "\n  </AppendedData>\n</VTKFile>\n");
}

void write_pvd(const std::string& path,
               const std::vector<std::pair<double, std::string>>& entries) {
  std::string body;
  body += "<?xml version=\"1.0\"?>\n";
  body += "<VTKFile type=\"Collection\" version=\"0.1\" byte_order=\"LittleEndian\">\n";
  body += "  <Collection>\n";
  for (const auto& [time, file] : entries)
    body += "    <DataSet timestep=\"" + fmt_double(time) + "\" group=\"\" part=\"0\" file=\"" +
            xml_escape(file) + "\"/>\n";
  body += "  </Collection>\n";
  body += "</VTKFile>\n";
  write_atomically(path, body, "", "");
}

}  // namespace dmi
