#include "verify/calculix.hpp"

#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <tuple>
#include <vector>

namespace dmi {
namespace {

// A structured brick mesh on a lattice of half-element steps: node (i, j, k) sits at x[i], y[j], z[k].
struct Lattice {
  std::vector<double> x, y, z;
  std::map<std::tuple<int, int, int>, int> ids;
  std::vector<std::array<int, 3>> order;
  int id(int i, int j, int k) {
    auto [it, added] = ids.try_emplace({i, j, k}, static_cast<int>(ids.size()) + 1);
    if (added) order.push_back({i, j, k});
    return it->second;
  }
};

// Edges of a grid of n cells over [a, b], refined to half steps.
std::vector<double> half_steps(const std::vector<double>& edges) {
  std::vector<double> out;
  for (std::size_t k = 0; k + 1 < edges.size(); ++k) out.push_back(edges[k]), out.push_back(0.5 * (edges[k] + edges[k + 1]));
  out.push_back(edges.back());
  return out;
}

// The 20 nodes of the brick whose lowest lattice corner is (i, j, k), in CalculiX's C3D20 order: corners of the
// face z-, then z+, edges of z-, of z+, then the edges along z.
std::array<int, 20> brick(Lattice& m, int i, int j, int k) {
  static const int c[20][3] = {{0, 0, 0}, {2, 0, 0}, {2, 2, 0}, {0, 2, 0}, {0, 0, 2}, {2, 0, 2}, {2, 2, 2}, {0, 2, 2},
                               {1, 0, 0}, {2, 1, 0}, {1, 2, 0}, {0, 1, 0}, {1, 0, 2}, {2, 1, 2}, {1, 2, 2}, {0, 1, 2},
                               {0, 0, 1}, {2, 0, 1}, {2, 2, 1}, {0, 2, 1}};
  std::array<int, 20> n{};
  for (int q = 0; q < 20; ++q) n[q] = m.id(i + c[q][0], j + c[q][1], k + c[q][2]);
  return n;
}

void write_materials(std::ostream& o, const CantileverPulse& p) {
  // Kinematic hardening: the stress at a plastic strain of 0.5 on the line of slope H = b E / (1 - b).
  const double H = p.hardening * p.E / (1 - p.hardening);
  o << "*MATERIAL, NAME=STEEL\n*ELASTIC\n" << p.E << ", " << p.nu << "\n*DENSITY\n" << p.rho << "\n";
  o << "*PLASTIC, HARDENING=KINEMATIC\n" << p.fy << ", 0.\n" << p.fy + 0.5 * H << ", 0.5\n";
  o << "*MATERIAL, NAME=BLOCK\n*ELASTIC\n" << p.E << ", " << p.nu << "\n*DENSITY\n" << p.block_density() << "\n";
  o << "*SOLID SECTION, ELSET=MEMBER, MATERIAL=STEEL\n*SOLID SECTION, ELSET=BLOCK, MATERIAL=BLOCK\n";
}

}  // namespace

std::string calculix_cantilever_input(const CantileverPulse& p, int along, int across) {
  if (along < 1 || across < 2 || across % 2) throw std::invalid_argument("calculix_cantilever_input: along >= 1, across even");
  Lattice m;
  std::vector<double> ex, ey;
  for (int k = 0; k <= along; ++k) ex.push_back(p.L * k / along);
  ex.push_back(p.L + p.block_length);
  for (int k = 0; k <= across; ++k) ey.push_back(-0.5 * p.d + p.d * k / across);
  m.x = half_steps(ex), m.y = half_steps(ey), m.z = half_steps({0.0, p.b});
  std::ostringstream elements, member, block, top;
  int count = 0;
  for (int i = 0; i <= along; ++i)
    for (int j = 0; j < across; ++j) {
      const std::array<int, 20> n = brick(m, 2 * i, 2 * j, 0);
      elements << ++count;
      for (int q = 0; q < 20; ++q) elements << (q == 15 ? ",\n" : ", ") << n[q];
      elements << "\n";
      (i < along ? member : block) << count << "\n";
      if (i == along && j == across - 1) top << count << ", P5, " << p.peak_force / (p.block_length * p.b) << "\n";
    }
  const int end = m.id(2 * along, across, 1);  // the cantilever's end, on its axis at mid-width
  std::ostringstream o;
  o.precision(12);
  o << "*NODE, NSET=ALL\n";
  for (const auto& [i, j, k] : m.order) o << m.ids[{i, j, k}] << ", " << m.x[i] << ", " << m.y[j] << ", " << m.z[k] << "\n";
  o << "*ELEMENT, TYPE=C3D20R\n" << elements.str();
  o << "*ELSET, ELSET=MEMBER\n" << member.str() << "*ELSET, ELSET=BLOCK\n" << block.str();
  write_materials(o, p);
  o << "*NSET, NSET=ROOT\n";
  for (const auto& [key, id] : m.ids)
    if (std::get<0>(key) == 0) o << id << "\n";
  o << "*NSET, NSET=END\n" << end << "\n";
  // The root held as beam theory holds it: plane (no axial displacement), the axis fixed across, the section free to
  // contract in its plane. A clamped face would also hold the plastic flow's contraction (incompressible: nu_p = 1/2)
  // and strengthen the root hinge.
  o << "*NSET, NSET=ROOT_AXIS\n";
  for (const auto& [key, id] : m.ids)
    if (std::get<0>(key) == 0 && std::get<1>(key) == across) o << id << "\n";
  o << "*BOUNDARY\nROOT, 1, 1, 0.\nROOT_AXIS, 2, 2, 0.\n" << m.id(0, across, 0) << ", 3, 3, 0.\n";
  o << "*AMPLITUDE, NAME=PULSE\n0., 0., " << 0.5 * p.td << ", 1., " << p.td << ", 0., " << 10 * p.duration << ", 0.\n";
  // Automatic increments no longer than our step (CalculiX shortens one whose Newton iterations do not converge).
  const double h = p.max_increment;
  o << "*STEP, NLGEOM, INC=1000000\n*DYNAMIC, ALPHA=0.\n" << h << ", " << p.duration << ", " << 1e-3 * h << ", " << h << "\n";
  // The pressure on the block's top face (S5, y+) pushes it towards -y.
  o << "*DLOAD, AMPLITUDE=PULSE\n" << top.str();
  o << "*NODE PRINT, NSET=END, FREQUENCY=1\nU\n*END STEP\n";
  return o.str();
}

SwayHistory parse_calculix_sway(const std::string& text) {
  SwayHistory h;
  std::istringstream in(text);
  std::string line;
  const std::string key = "displacements (vx,vy,vz) for set END and time";
  while (std::getline(in, line)) {
    const std::size_t at = line.find(key);
    if (at == std::string::npos) continue;
    const double t = std::stod(line.substr(at + key.size()));
    std::string row;
    while (std::getline(in, row) && row.find_first_not_of(" \t\r") == std::string::npos) {
    }
    std::istringstream r(row);
    int node = 0;
    double ux = NAN, uy = NAN;
    if (!(r >> node >> ux >> uy)) throw std::runtime_error("CalculiX output: no displacement after the time " + std::to_string(t));
    h.t.push_back(t), h.sway.push_back(-uy);
  }
  if (h.t.empty()) throw std::runtime_error("CalculiX output: no displacements of the set END");
  return h;
}

SwayHistory calculix_cantilever_sway(const CantileverPulse& p, int along, int across, const std::string& work_dir) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::path(work_dir) / ("cantilever_" + std::to_string(along) + "x" + std::to_string(across));
  fs::create_directories(dir);
  std::ofstream(dir / "cantilever.inp") << calculix_cantilever_input(p, along, across);
  const std::string cmd = "cd '" + dir.string() + "' && ccx -i cantilever > ccx.log 2>&1";
  if (std::system(cmd.c_str()) != 0) throw std::runtime_error("ccx failed or is not installed (see " + (dir / "ccx.log").string() + ")");
  std::ifstream dat(dir / "cantilever.dat");
  std::stringstream text;
  text << dat.rdbuf();
  return parse_calculix_sway(text.str());
}

}  // namespace dmi
