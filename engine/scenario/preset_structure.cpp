// The presets' dam: the concrete gravity dam (members or continuum), the steel open dam (plane or space frame), the
// members' damping, and the tyre buffer on the upstream face.
#include "engine/scenario/preset_builder.hpp"

namespace dmi::preset_build {

void Builder::add_dam() {
  if (d_.type == "concrete_gravity") {
    json m = d_.concrete;
    m["name"] = "concrete";
    // No damping on the continuum dam: Kelvin-Voigt damping is stiffness-proportional, and for concrete at
    // the first mode it cut the explicit step 70-fold (0.05 s took 509 000 steps, 487 s); damping_ratio
    // applies to the members model (Rayleigh on the frame, which Newmark integrates implicitly).
    materials_.push_back(m);
    if (members_) return add_concrete_members();
    if (d_.deposit_height > 0 || d_.water_height > 0)
      fail("/dam/model", json("continuum"), "the members model with a deposit or water behind the dam (their pressures load the members)");
    json poly = json::array({{xu(0), 0.0}, {xd(0), 0.0}, {xd(d_.height), d_.height}, {xu(d_.height), d_.height}});
    bodies_.push_back(json{{"name", "dam"}, {"material", "concrete"}, {"shape", {{"type", "polygon"}, {"vertices", poly}}}});
    probes_.push_back(json{{"name", "dam"}, {"type", "body"}, {"body", "dam"}, {"quantities", {"displacement", "velocity"}}});
    box_.add(xu(0), 0), box_.add(xd(0), d_.height);
    return;
  }
  json m = d_.steel;
  m["name"] = "steel";
  materials_.push_back(m);
  add_steel_frame();
}

void Builder::add_concrete_members() {
  const double H = d_.height;
  const double x0 = 0.5 * (xu(0) + xd(0)), x1 = 0.5 * (xu(H) + xd(H));
  // Depth normal to the (slightly inclined) centre line: the horizontal thickness times cos(phi).
  const double c = H / std::hypot(H, x1 - x0);
  json st;
  st["integrator"] = "newmark";
  st["theory"] = d_.beam_theory;
  st["self_weight"] = true;
  st["nodes"] = json::array({{{"name", "base"}, {"position", at(x0, 0.0)}}, {{"name", "crest"}, {"position", at(x1, H)}}});
  st["members"] = json::array({{{"name", "dam"}, {"start", "base"}, {"end", "crest"}, {"material", "concrete"}, {"elements", d_.elements},
                                {"section", {{"type", "tapered_rectangle"}, {"width", d_.width}, {"depth_start", d_.base_thickness * c},
                                             {"depth_end", d_.crest * c}}}}});
  st["supports"] = json::array({{{"node", "base"}, {"type", d_.base}}});
  // What stands behind the dam: pressures on the upstream face (along the flow), over the face width.
  json pl = json::array();
  if (d_.deposit_height > 0)
    pl.push_back({{"member", "dam"}, {"direction", at(1.0, 0.0)}, {"surface", d_.deposit_height},
                  {"gradient", d_.deposit_coefficient * d_.deposit_unit_weight * d_.width}});
  if (d_.deposit_height > 0 && d_.deposit_submerged)  // the buoyancy of the submerged part: K gamma_w (min(h, h_w) - y) upstream
    pl.push_back({{"member", "dam"}, {"direction", at(-1.0, 0.0)}, {"surface", std::min(d_.deposit_height, d_.water_height)},
                  {"gradient", d_.deposit_coefficient * d_.water_unit_weight * d_.width}});
  if (d_.water_height > 0)
    pl.push_back({{"member", "dam"}, {"direction", at(1.0, 0.0)}, {"surface", d_.water_height}, {"gradient", d_.water_unit_weight * d_.width}});
  if (!pl.empty()) st["pressure_loads"] = pl;
  damp(st, d_.concrete, 0.5 * (d_.base_thickness + d_.crest) * c / std::sqrt(12.0));
  out_["structure"] = st;
  face_ = json{{"members", {"dam"}}, {"direction", at(1.0, 0.0)}};
  if (dim_ == 3) face_["width"] = d_.width;
  box_.add(xu(0), 0), box_.add(xd(0), H), box_.add(xu(H), H);
  if (dim_ == 3) return;  // member probes are plane-frame only (the space frame's histories carry every section force)
  probes_.push_back(json{{"name", "base"}, {"type", "member"}, {"member", "dam"}, {"position", 0.0}, {"quantities", {"section_forces", "fibre_stress"}}});
  probes_.push_back(json{{"name", "crest"}, {"type", "member"}, {"member", "dam"}, {"position", 1.0}, {"quantities", {"displacement"}}});
}

void Builder::add_steel_frame() {
  if (dim_ == 3) return add_space_steel_frame();
  const double H = d_.height, D = d_.column_d, s = d_.row_spacing;
  const double bd = d_.beam_d > 0 ? d_.beam_d : D, bt = d_.beam_t > 0 ? d_.beam_t : d_.column_t;
  json nodes = json::array(), members = json::array(), supports = json::array();
  auto node = [](int i, int k) { return "c" + std::to_string(i) + "_" + std::to_string(k); };
  const int secondary = std::max(2, d_.elements / 2);
  for (int i = 0; i < d_.rows; ++i) {
    const double x = 0.5 * D + i * s;  // the upstream column's upstream surface is at x = 0
    for (int k = 0; k <= d_.levels; ++k) {
      nodes.push_back({{"name", node(i, k)}, {"position", {x, H * k / d_.levels}}});
      if (k == 0) {
        supports.push_back({{"node", node(i, 0)}, {"type", d_.base}});
        continue;
      }
      const std::string tag = std::to_string(i) + "_" + std::to_string(k);
      members.push_back({{"name", "column_" + tag}, {"start", node(i, k - 1)}, {"end", node(i, k)}, {"material", "steel"},
                         {"elements", d_.elements}, {"section", pipe(D, d_.column_t)}});
      if (i + 1 == d_.rows) continue;
      members.push_back({{"name", "beam_" + tag}, {"start", node(i, k)}, {"end", node(i + 1, k)}, {"material", "steel"},
                         {"elements", secondary}, {"section", pipe(bd, bt)}});
      if (d_.bracing)
        members.push_back({{"name", "brace_" + tag}, {"start", node(i + 1, k - 1)}, {"end", node(i, k)}, {"material", "steel"},
                           {"elements", secondary}, {"section", pipe(bd, bt)}});
    }
  }
  json st{{"integrator", "newmark"}, {"theory", d_.beam_theory}, {"self_weight", true}, {"nodes", nodes}, {"members", members}, {"supports", supports}};
  damp(st, d_.steel, std::sqrt(D * D + std::pow(D - 2 * d_.column_t, 2)) / 4);  // pipe: r^2 = (D^2 + d^2) / 16
  out_["structure"] = st;
  face_ = json{{"members", json::array()}, {"direction", at(1.0, 0.0)}};  // the upstream column line
  for (int k = 1; k <= d_.levels; ++k) face_["members"].push_back("column_0_" + std::to_string(k));
  box_.add(0, 0), box_.add(xd(0), H + 0.5 * D);
  probes_.push_back(json{{"name", "base"}, {"type", "member"}, {"member", "column_0_1"}, {"position", 0.0},
                         {"quantities", {"section_forces", "fibre_stress"}}});
  probes_.push_back(json{{"name", "crest"}, {"type", "member"}, {"member", "column_0_" + std::to_string(d_.levels)}, {"position", 1.0},
                         {"quantities", {"displacement"}}});
}

// The steel open dam in 3D: `columns` pipe columns per row across the channel, `width` apart and centred on y = 0, the
// rows along the flow as in 2D; at every level beams along the flow (and one brace per panel) in each column line,
// and ties across the channel between neighbouring columns of a row.
void Builder::add_space_steel_frame() {
  const double H = d_.height, D = d_.column_d, s = d_.row_spacing;
  const double bd = d_.beam_d > 0 ? d_.beam_d : D, bt = d_.beam_t > 0 ? d_.beam_t : d_.column_t;
  const int nc = columns(), secondary = std::max(2, d_.elements / 2);
  if (nc > 1 && !(d_.width > D)) fail("/dam/width", d_.width, "a column spacing across the channel larger than the column diameter (the columns would overlap)");
  json nodes = json::array(), members = json::array(), supports = json::array();
  auto node = [](int i, int j, int k) { return "c" + std::to_string(i) + "_" + std::to_string(j) + "_" + std::to_string(k); };
  auto across = [&](int j) { return (j - 0.5 * (nc - 1)) * d_.width; };
  auto member = [&](const std::string& name, const std::string& a, const std::string& b, int elements, double d, double t) {
    members.push_back({{"name", name}, {"start", a}, {"end", b}, {"material", "steel"}, {"elements", elements}, {"section", pipe(d, t)}});
  };
  for (int i = 0; i < d_.rows; ++i)
    for (int j = 0; j < nc; ++j)
      for (int k = 0; k <= d_.levels; ++k) {
        nodes.push_back({{"name", node(i, j, k)}, {"position", at(0.5 * D + i * s, H * k / d_.levels, across(j))}});
        if (k == 0) {
          supports.push_back({{"node", node(i, j, 0)}, {"type", d_.base}});
          continue;
        }
        const std::string tag = std::to_string(i) + "_" + std::to_string(j) + "_" + std::to_string(k);
        member("column_" + tag, node(i, j, k - 1), node(i, j, k), d_.elements, D, d_.column_t);
        if (i + 1 < d_.rows) {
          member("beam_" + tag, node(i, j, k), node(i + 1, j, k), secondary, bd, bt);
          if (d_.bracing) member("brace_" + tag, node(i + 1, j, k - 1), node(i, j, k), secondary, bd, bt);
        }
        if (j + 1 < nc) member("tie_" + tag, node(i, j, k), node(i, j + 1, k), secondary, bd, bt);
      }
  json st{{"integrator", "newmark"}, {"theory", d_.beam_theory}, {"self_weight", true}, {"nodes", nodes}, {"members", members}, {"supports", supports}};
  damp(st, d_.steel, std::sqrt(D * D + std::pow(D - 2 * d_.column_t, 2)) / 4);  // pipe: r^2 = (D^2 + d^2) / 16
  out_["structure"] = st;
  box_.add(0, 0), box_.add(xd(0), H + 0.5 * D);
  box_.across(across(0) - 0.5 * D, across(nc - 1) + 0.5 * D);
}

void Builder::damp(json& st, const json& material, double r) {
  const auto modes = cantilever_modes(material["youngs_modulus"], material["density"], r, d_.height);
  period_ = 2 * kPi / modes.first;
  if (!(d_.damping_ratio > 0)) return;
  if (d_.damping_model == "modal") st["modal_damping"] = json{{"ratio", d_.damping_ratio}};
  else st["rayleigh_damping"] = rayleigh(d_.damping_ratio, modes, d_.damping_model);
}

double Builder::buffer_damping_frequency(double E, double thickness) const {
  // The buffer works as a spring k = E A / t under the boulder (A = r x W, a contact strip as wide as the
  // equivalent radius) against the boulder's mass: f = sqrt(k/m) / (2 pi). Without a boulder, the
  // layer's own quarter-wave frequency c / (4 t) (an estimate: the ratio is exact only at this frequency).
  // In 3D the sphere presses A = pi r^2 (the design basis's assumption, docs/design-checks.md).
  const double A = dim_ == 3 ? kPi * boulder_r_ * boulder_r_ : boulder_r_ * d_.width;
  if (p_.boulder) return std::sqrt(E * A / thickness / boulder_m_) / (2 * kPi);
  const double rho = p_.buffer->material.value("density", 600.0);
  return std::sqrt(E / rho) / (4 * thickness);
}

void Builder::add_buffer() {
  const BufferPreset& b = *p_.buffer;
  const double H = d_.height;
  const double top = b.top > 0 ? b.top : H;
  if (top > H) fail("/tyre_buffer/top", top, "a top at most the dam height " + std::to_string(H) + " m");
  if (top <= b.bottom) fail("/tyre_buffer/top", top, "a top above bottom = " + std::to_string(b.bottom) + " m");
  p_.buffer->top = top;  // front() reads the resolved top
  json m = b.material;
  const bool homog = b.type == "homogenised";
  m["name"] = homog ? "tyre_buffer" : "tyre_rubber";
  const double E = m["youngs_modulus"], nu = m["poisson_ratio"];
  const double f = m.contains("damping_frequency") ? m["damping_frequency"].get<double>()
                                                   : buffer_damping_frequency(E, homog ? b.thickness : b.tyre_diameter);
  if (b.viscosity > 0) {
    // Kelvin-Voigt: sigma_v = beta C:D, shear part 2 mu beta D' = 2 eta D'  ->  beta = eta / mu; zeta(f) = pi f beta.
    const double zeta = kPi * f * b.viscosity / (E / (2 * (1 + nu)));
    if (zeta > 1) fail("/tyre_buffer/viscosity", b.viscosity, "a viscosity giving a damping ratio <= 1 at " + std::to_string(f) + " Hz (it gives " +
                                                                 std::to_string(zeta) + ")");
    m["damping_ratio"] = zeta;
  }
  if (m.value("damping_ratio", 0.0) > 0 && !m.contains("damping_frequency")) m["damping_frequency"] = f;
  materials_.push_back(m);
  if (homog && dim_ == 3) {  // a box on the vertical upstream face, across the whole crest (presets.cpp allows no other)
    const double t = b.thickness, y0 = std::max(b.bottom, bed(-t)), w = 0.5 * d_.width;
    bodies_.push_back(json{{"name", "buffer"}, {"material", m["name"]}, {"shape", {{"type", "box"}, {"min", at(-t, y0, -w)}, {"max", at(0.0, top, w)}}}});
    bonded_.push_back("buffer");
    box_.add(-t, y0), box_.add(-t, top), box_.across(-w, w);
    return;
  }
  if (homog) {
    const double t = b.thickness;
    const double y0 = std::max(b.bottom, bed(xu(b.bottom) - t));
    json poly = json::array({{xu(y0) - t, y0}, {xu(y0), y0}, {xu(top), top}, {xu(top) - t, top}});
    bodies_.push_back(json{{"name", "buffer"}, {"material", m["name"]}, {"shape", {{"type", "polygon"}, {"vertices", poly}}}});
    bonded_.push_back("buffer");
    box_.add(xu(y0) - t, y0), box_.add(xu(top) - t, top);
    return;
  }
  const double R = 0.5 * b.tyre_diameter, inner = R - b.ring_thickness;
  if (inner <= 0) fail("/tyre_buffer/ring_thickness", b.ring_thickness, "a ring thickness below the tyre radius " + std::to_string(R) + " m");
  if (b.fill != "none") {
    const bool sand = b.fill == "sand";
    materials_.push_back(json{{"name", "tyre_fill"}, {"model", "drucker_prager"}, {"density", sand ? 1800 : 2000},
                              {"youngs_modulus", sand ? 30e6 : 80e6}, {"poisson_ratio", 0.3}, {"friction_angle", sand ? 35 : 40}});
  }
  int n = 0;
  for (double y = std::max(b.bottom, 0.0) + R; y + R <= top + 1e-9; y += 2 * R, ++n) {
    const std::string name = "tyre_" + std::to_string(n + 1);
    const double x = xu(y) - R;
    bodies_.push_back(json{{"name", name}, {"material", "tyre_rubber"},
                           {"shape", {{"type", "ball"}, {"center", {x, y}}, {"radius", R}, {"inner_radius", inner}}}});
    bonded_.push_back(name);
    if (b.fill != "none")
      bodies_.push_back(json{{"name", name + "_fill"}, {"material", "tyre_fill"},
                             {"shape", {{"type", "ball"}, {"center", {x, y}}, {"radius", inner * (1 - 1e-9)}}}});
    box_.add(x - R, y - R), box_.add(x + R, y + R);
  }
  if (n == 0) fail("/tyre_buffer/tyre_diameter", b.tyre_diameter, "tyres that fit between bottom and top (" + std::to_string(top - b.bottom) + " m)");
}

}  // namespace dmi::preset_build
