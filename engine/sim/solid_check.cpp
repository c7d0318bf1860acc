#include "engine/sim/solid_check.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <map>
#include <memory>
#include <mutex>

#include <nlohmann/json.hpp>

#include "engine/common/error.hpp"
#include "engine/solid/loads.hpp"
#include "engine/solid/mesh.hpp"
#include "engine/solid/static_solver.hpp"
#include "engine/solid/stress.hpp"

namespace dmi {

using json = nlohmann::json;
using namespace dmi::solid;

namespace {

struct Model {
  TaperedBlock block;
  Mesh mesh;
  Elastic mat;
  std::vector<int> base;
};

Model make_model(const SolidCheckConfig& c) {
  Model m;
  TaperedBlock& b = m.block;
  b.height_m = c.height;
  b.width_m = c.width;
  b.base_thickness_m = c.base_thickness;
  b.crest_thickness_m = c.crest_thickness;
  b.sloped = parse_sloped_face(c.sloped_face);
  b.nx = c.cells[0], b.ny = c.cells[1], b.nz = c.cells[2];
  const bool hex = c.element == "hex8";
  m.mesh = hex ? hex8_tapered_block(b) : quad4_tapered_section(b);
  m.mat.E_Pa = c.youngs_modulus;
  m.mat.nu = c.poisson_ratio;
  m.mat.analysis = hex ? Analysis::solid3d : Analysis::plane_strain;
  m.mat.thickness_m = c.width;
  m.base = nodes_at_height(m.mesh, 0.0, 1e-9 * c.height);
  return m;
}

// Horizontal contact loads on one member binned by height (bins of width dz from z = 0), as samples of
// a piecewise-linear pressure: each bin a hat of half-width dz, so the integral is sum(F_x) / W.
std::pair<std::vector<double>, std::vector<double>> contact_profile(const PeakContact& pc, const std::string& member, double dz, double W,
                                                                    double H, double& resultant) {
  std::map<long, double> bins;
  resultant = 0;
  for (const ContactLoadAt& l : pc.loads) {
    if (!member.empty() && l.member != member) continue;
    const double z = std::clamp(l.point[1], 0.0, H), fx = l.force[0];
    bins[static_cast<long>(std::floor(z / dz))] += fx;
    resultant += fx;
  }
  std::vector<double> z, q;
  for (const auto& [k, f] : bins) {
    const double zc = (k + 0.5) * dz;
    if (z.empty()) {
      z.push_back(zc - dz), q.push_back(0.0);
    } else if (zc - z.back() > 1.5 * dz) {  // a gap: close the previous hat, open this one
      z.push_back(z.back() + dz), q.push_back(0.0);
      if (zc - dz > z.back() + 1e-12 * dz) z.push_back(zc - dz), q.push_back(0.0);
    }
    z.push_back(zc), q.push_back(f / (dz * W));
  }
  if (!z.empty()) z.push_back(z.back() + dz), q.push_back(0.0);
  return {z, q};
}

std::map<std::string, std::map<std::string, SolidPeak>> stress_peaks(const Model& m, const StressField& field) {
  std::map<std::string, std::map<std::string, SolidPeak>> out;
  const std::vector<Measure> ms = {Measure::von_mises, Measure::max_principal, Measure::min_principal, Measure::max_shear};
  const char* keys[] = {"von_mises", "max_principal", "min_principal", "max_shear"};
  for (const auto& [loc, where] : {std::pair{Location::gauss, "gauss"}, std::pair{Location::centroid, "centroid"}, std::pair{Location::node, "node"}}) {
    const std::vector<Peak> pk = peaks(field, ms, loc);
    for (std::size_t k = 0; k < ms.size(); ++k) {
      const Eigen::VectorXd x = point_coordinates(m.mesh, loc, pk[k].index);
      out[keys[k]][where] = {measure(field.at(loc)[pk[k].index], ms[k]), std::vector<double>(x.data(), x.data() + x.size())};
    }
  }
  return out;
}

// The model and its factorised stiffness depend on the dam's geometry, mesh, material and supports only, not on the
// loads: the variants of a scenario and the cases of a sweep check one dam, and the factorisation is most of a check's
// time (0.7 s of 0.75 s on the demo's dam). The last few are kept per process.
struct Factorised {
  Model m;
  StaticSolver solver;
  explicit Factorised(Model model) : m(std::move(model)), solver(assemble_stiffness(m.mesh, m.mat), node_dofs(m.mesh, m.base)) {}
};

std::shared_ptr<const Factorised> factorised(const SolidCheckConfig& c) {
  char key[512];
  std::snprintf(key, sizeof key, "%.17g %.17g %.17g %.17g %s %d %d %d %s %.17g %.17g", c.height, c.width, c.base_thickness, c.crest_thickness,
                c.sloped_face.c_str(), c.cells[0], c.cells[1], c.cells[2], c.element.c_str(), c.youngs_modulus, c.poisson_ratio);
  static std::mutex mu;
  static std::deque<std::pair<std::string, std::shared_ptr<const Factorised>>> kept;
  const std::lock_guard<std::mutex> lock(mu);
  for (const auto& [k, f] : kept)
    if (k == key) return f;
  auto f = std::make_shared<const Factorised>(make_model(c));
  kept.emplace_front(key, f);
  if (kept.size() > 2) kept.pop_back();
  return f;
}


// v to 6 significant digits: the field document stays compact (its JSON prints the shortest round-trip form).
double sig6(double v) {
  if (v == 0 || !std::isfinite(v)) return v;
  const double p = std::pow(10.0, 5 - std::floor(std::log10(std::abs(v))));
  return std::round(v * p) / p;
}

SolidFieldCase field_case(const std::string& name, const Eigen::VectorXd& u, const StressField& field) {
  SolidFieldCase c;
  c.name = name;
  for (const Stress6& st : field.nodal)
    c.von_mises_Pa.push_back(sig6(measure(st, Measure::von_mises))), c.max_principal_Pa.push_back(sig6(measure(st, Measure::max_principal)));
  for (Eigen::Index k = 0; k < u.size(); ++k) c.displacement_m.push_back(sig6(u[k]));
  return c;
}

}  // namespace

void prepare_solid_check(const SolidCheckConfig& c) {
  try {
    factorised(c);
  } catch (...) {  // run_solid_check meets the same error and reports it
  }
}

namespace {

// A point or patch load case on the upstream face (in 2D a patch is its vertical profile over the plane-strain width).
void given_load(const Model& m, const SolidCheckConfig& c, const SolidLoadConfig& l, Eigen::VectorXd& f) {
  const int dim = m.mesh.dim;
  const double across = l.across >= 0 ? l.across : 0.5 * c.width;
  if (l.type == "point") {
    Eigen::VectorXd F = Eigen::VectorXd::Zero(dim);
    F[0] = l.force;
    add_point_load(m.mesh, nearest_face_node(m.mesh, Face::upstream, across, l.height), F, f);
  } else if (dim == 3) {
    PatchLoad p;
    p.centre_y_m = across, p.centre_z_m = l.height, p.width_m = l.patch_width, p.height_m = l.patch_height;
    p.total_force_N = l.force;
    p.shape = l.shape == "uniform" ? PatchShape::uniform : PatchShape::pyramid;
    add_patch_load(m.mesh, p, f);
  } else {
    const double h = 0.5 * l.patch_height, W = c.width;
    if (l.shape == "uniform")
      add_pressure_profile(m.mesh, m.mat, Face::upstream, {l.height - h, l.height + h}, {l.force / (W * 2 * h), l.force / (W * 2 * h)}, f);
    else
      add_pressure_profile(m.mesh, m.mat, Face::upstream, {l.height - h, l.height, l.height + h}, {0.0, l.force / (W * h), 0.0}, f);
  }
}

// The simulation's contact loads at their peak on one member, binned by height into a pressure profile on the face;
// in 3D turned about its centroid into a round patch with the simulation's resultant (or spread uniformly across).
void simulation_load(const Scenario& s, const Model& m, const SolidLoadConfig& l, std::size_t i, const PeakContact* contact, SolidCase& entry,
                     Eigen::VectorXd& f) {
  const SolidCheckConfig& c = s.solid_check;
  if (!contact)
    throw InputError(s.message_source(), "/solid_check/loads/" + std::to_string(i) + "/type", "\"simulation\"",
                     "a run in which the members were touched (no contact loads were recorded)");
  const std::string member = l.member.empty() ? s.structure.members.front().name : l.member;
  double resultant = 0;
  const auto [z, q] = contact_profile(*contact, member, s.grid.cell_size, c.width, c.height, resultant);
  entry.time_s = contact->time;
  entry.member = member;
  entry.profile = SolidProfile{z, q};
  if (z.size() < 2 || !(std::abs(resultant) > 0)) {
    entry.note = "no horizontal contact load on the member at the governing instant";
  } else if (m.mesh.dim == 2 || l.spread == "uniform") {
    add_pressure_profile(m.mesh, m.mat, Face::upstream, z, q, f);
  } else {  // a round patch: the vertical profile, symmetrised about its centroid, turned about it
    const double across = l.across >= 0 ? l.across : 0.5 * c.width;
    double zc = 0, sum = 0;
    for (std::size_t k = 0; k < z.size(); ++k) zc += q[k] * z[k], sum += q[k];
    zc /= sum;
    FaceTraction t;
    t.q_Pa = [&, zc](double y, double zz) {
      const double r = std::hypot(y - across, zz - zc);
      return 0.5 * (piecewise_linear(z, q, zc + r) + piecewise_linear(z, q, zc - r));
    };
    t.gauss_per_direction = 4;
    Eigen::VectorXd g = Eigen::VectorXd::Zero(f.size());
    const FaceLoadReport rep = add_face_traction(m.mesh, m.mat, t, g);
    f += g * (resultant / rep.resultant_N);  // same resultant as the simulation
  }
}

// A load case's answer: its resultant, stress peaks, base reactions and largest displacement.
void record_case(const Model& m, const Eigen::VectorXd& f, const StaticSolution& sol, const StressField& field, SolidCase& entry) {
  const int dim = m.mesh.dim;
  double fx = 0;
  for (int n = 0; n < m.mesh.n_nodes(); ++n) fx += f[dim * n];
  double rmax = 0, umax = 0;
  for (int n : m.base) rmax = std::max(rmax, sol.reaction.segment(dim * n, dim).norm());
  for (int n = 0; n < m.mesh.n_nodes(); ++n) umax = std::max(umax, sol.u.segment(dim * n, dim).norm());
  const Eigen::VectorXd total = total_reaction(m.mesh, sol.reaction, m.base);
  entry.load_resultant_N = fx;
  entry.peaks = stress_peaks(m, field);
  entry.max_nodal_base_reaction_N = rmax;
  entry.total_base_reaction_N.assign(total.data(), total.data() + total.size());
  entry.max_displacement_m = umax;
}

// The mesh and the load cases' fields, for the pictures.
SolidFieldRecord solid_field(const Model& m, const std::string& axes, std::vector<SolidFieldCase> cases) {
  SolidFieldRecord f;
  f.dim = m.mesh.dim, f.nodes_per_element = m.mesh.nodes_per_element(), f.axes = axes;
  for (int n = 0; n < m.mesh.n_nodes(); ++n)
    for (int d = 0; d < f.dim; ++d) f.nodes_m.push_back(sig6(m.mesh.nodes(n, d)));
  for (int e = 0; e < m.mesh.n_elements(); ++e)
    for (int c2 = 0; c2 < m.mesh.nodes_per_element(); ++c2) f.elements.push_back(m.mesh.elements(e, c2));
  f.cases = std::move(cases);
  return f;
}

}  // namespace

SolidCheckDocuments run_solid_check(const Scenario& s, const PeakContact* contact) {
  const SolidCheckConfig& c = s.solid_check;
  const std::shared_ptr<const Factorised> fm = factorised(c);
  const Model& m = fm->m;
  const int dim = m.mesh.dim;
  SolidCheckRecord check;
  std::vector<SolidFieldCase> field_cases;
  for (std::size_t i = 0; i < c.loads.size(); ++i) {
    const SolidLoadConfig& l = c.loads[i];
    Eigen::VectorXd f = Eigen::VectorXd::Zero(m.mesh.n_dofs());
    SolidCase entry;
    entry.name = l.name, entry.type = l.type;
    if (l.type == "point" || l.type == "patch")
      given_load(m, c, l, f);
    else
      simulation_load(s, m, l, i, contact, entry, f);
    const StaticSolution sol = fm->solver.solve(f);
    const StressField field = recover_stress(m.mesh, m.mat, sol.u);
    record_case(m, f, sol, field, entry);
    check.cases.push_back(std::move(entry));
    field_cases.push_back(field_case(l.name, sol.u, field));
  }
  SolidModel& model = check.model;
  model.element = c.element, model.cells = c.cells, model.nodes = m.mesh.n_nodes(), model.elements = m.mesh.n_elements();
  model.height_m = c.height, model.crest_thickness_m = c.crest_thickness, model.base_thickness_m = c.base_thickness, model.width_m = c.width;
  model.sloped_face = c.sloped_face, model.youngs_modulus_Pa = c.youngs_modulus, model.poisson_ratio = c.poisson_ratio;
  model.axes = dim == 3 ? "x through the thickness (downstream), y across the face, z up" : "x through the thickness (downstream), z up";
  SolidFieldRecord field = solid_field(m, model.axes, std::move(field_cases));
  return {std::move(check), std::move(field)};
}

}  // namespace dmi
