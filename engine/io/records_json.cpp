#include "engine/io/records_json.hpp"

#include <cmath>
#include <stdexcept>

namespace dmi {

nlohmann::json peak_contact_to_json(const PeakContact& p) {
  nlohmann::json loads = nlohmann::json::array();
  for (const ContactLoadAt& l : p.loads) loads.push_back({{"member", l.member}, {"position", l.position}, {"point", l.point}, {"force", l.force}});
  return {{"time", p.time}, {"total_force", p.total_force}, {"units", {{"time", "s"}, {"point", "m"}, {"force", "N"}}}, {"loads", loads}};
}

PeakContact peak_contact_from_json(const nlohmann::json& j, const std::string& where) {
  try {
    PeakContact p;
    p.time = j.at("time").get<double>();
    p.total_force = j.at("total_force").get<std::vector<double>>();
    const std::size_t dim = p.total_force.size();
    if (dim != 2 && dim != 3) throw std::out_of_range("total_force has " + std::to_string(dim) + " components (2 or 3)");
    if (!j.at("loads").is_array()) throw std::out_of_range("loads is not an array");
    for (const auto& l : j.at("loads")) {
      p.loads.push_back({l.at("member").get<std::string>(), l.at("position").get<double>(), l.at("point").get<std::vector<double>>(),
                         l.at("force").get<std::vector<double>>()});
      if (p.loads.back().point.size() != dim || p.loads.back().force.size() != dim)
        throw std::out_of_range("a load's point or force without " + std::to_string(dim) + " components");
    }
    return p;
  } catch (const std::exception& e) {
    throw std::runtime_error(where + " is malformed (" + std::string(e.what()) + ")");
  }
}

namespace {

using nlohmann::json;

json section_json(const SectionRecord& c) {
  json sec{{"kind", c.kind}};
  if (c.kind == "pipe") {
    sec["diameter_m"] = c.diameter_m;
    sec["wall_thickness_m"] = c.wall_thickness_m;
  } else {
    sec["width_m"] = c.width_m;
    sec["depth_start_m"] = c.depth_start_m;
    sec["depth_end_m"] = c.depth_end_m;
  }
  if (c.kind == "box") sec["wall_thickness_m"] = c.wall_thickness_m;
  if (c.kind == "i_section") sec["flange_thickness_m"] = c.flange_thickness_m, sec["web_thickness_m"] = c.web_thickness_m;
  return sec;
}

SectionRecord section_from(const json& s) {
  SectionRecord c;
  c.kind = s.at("kind").get<std::string>();
  if (c.kind == "pipe") {
    c.diameter_m = s.at("diameter_m"), c.wall_thickness_m = s.at("wall_thickness_m");
  } else if (c.kind == "rectangle" || c.kind == "tapered_rectangle" || c.kind == "box" || c.kind == "i_section") {
    c.width_m = s.at("width_m"), c.depth_start_m = s.at("depth_start_m"), c.depth_end_m = s.at("depth_end_m");
    if (c.kind == "box") c.wall_thickness_m = s.at("wall_thickness_m");
    if (c.kind == "i_section") c.flange_thickness_m = s.at("flange_thickness_m"), c.web_thickness_m = s.at("web_thickness_m");
  } else {
    throw std::out_of_range("section kind '" + c.kind + "'");
  }
  return c;
}

// An index: a whole number, not a number rounded or a boolean taken for one.
int index_at(const json& o, const char* key) {
  const json& v = o.at(key);
  if (!v.is_number_integer()) throw std::out_of_range(std::string(key) + " is not a whole number");
  return v.get<int>();
}

ElementRecord element_from(const json& e, int dim, std::size_t nodes) {
  ElementRecord el;
  el.member = index_at(e, "member"), el.i = index_at(e, "i"), el.j = index_at(e, "j"), el.s0 = e.at("s0"), el.s1 = e.at("s1");
  el.section = section_from(e.at("section"));
  el.youngs_modulus_Pa = e.at("youngs_modulus_Pa"), el.poisson_ratio = e.value("poisson_ratio", 0.0), el.density_kg_m3 = e.value("density_kg_m3", 0.0);
  el.yield_strength_Pa = e.value("yield_strength_Pa", 0.0), el.hardening_ratio = e.value("hardening_ratio", 0.0);
  el.steel_curve = e.value("steel_curve", std::string());
  if (dim == 3) el.e2 = {e.at("e2").at(0).get<double>(), e.at("e2").at(1).get<double>(), e.at("e2").at(2).get<double>()};
  if (el.i < 0 || el.j < 0 || el.i >= int(nodes) || el.j >= int(nodes)) throw std::out_of_range("element node index");
  if (!(el.s0 >= 0 && el.s0 < el.s1 && el.s1 <= 1)) throw std::out_of_range("element span s0, s1 outside 0 <= s0 < s1 <= 1");
  return el;
}

}  // namespace

json structure_to_json(const StructureRecord& s) {
  json elements = json::array(), members = json::array(), supports = json::array();
  for (const ElementRecord& e : s.elements) {
    elements.push_back({{"member", e.member}, {"i", e.i}, {"j", e.j}, {"s0", e.s0}, {"s1", e.s1}, {"section", section_json(e.section)},
                        {"youngs_modulus_Pa", e.youngs_modulus_Pa}, {"poisson_ratio", e.poisson_ratio}, {"density_kg_m3", e.density_kg_m3}});
    if (e.yield_strength_Pa > 0) {
      elements.back()["yield_strength_Pa"] = e.yield_strength_Pa;
      elements.back()["hardening_ratio"] = e.hardening_ratio;
      if (!e.steel_curve.empty()) elements.back()["steel_curve"] = e.steel_curve;
    }
    if (s.dimension == 3) elements.back()["e2"] = e.e2;
  }
  for (const MemberRecord& m : s.members)
    members.push_back({{"name", m.name}, {"material", m.material}, {"first_element", m.first_element}, {"elements", m.elements}});
  for (const SupportRecord& d : s.supports)
    supports.push_back({{"node", d.node}, {"node_index", d.node_index}, {"type", d.type}, {"fixed", d.fixed}, {"series", d.series}});
  return {{"dimension", s.dimension}, {"nodes_m", s.nodes_m}, {"node_names", s.node_names}, {"elements", elements}, {"members", members},
          {"supports", supports}, {"gravity_m_s2", s.gravity_m_s2}, {"plane_thickness_m", s.plane_thickness_m}};
}

StructureRecord structure_from_json(const json& j, const std::string& where) {
  try {
    StructureRecord s;
    s.dimension = j.value("dimension", 2);
    if (s.dimension != 2 && s.dimension != 3) throw std::out_of_range("dimension " + std::to_string(s.dimension) + " (2 or 3)");
    for (const auto& n : j.at("nodes_m")) {
      if (n.size() != std::size_t(s.dimension)) throw std::out_of_range("a node with " + std::to_string(n.size()) + " coordinates");
      s.nodes_m.push_back(n.get<std::vector<double>>());
    }
    s.node_names = j.value("node_names", std::vector<std::string>(s.nodes_m.size()));
    if (s.node_names.size() != s.nodes_m.size()) throw std::out_of_range("node_names and nodes_m differ in length");
    for (const auto& e : j.at("elements")) s.elements.push_back(element_from(e, s.dimension, s.nodes_m.size()));
    for (const auto& m : j.at("members")) {
      MemberRecord mb{m.at("name"), m.at("material"), index_at(m, "first_element"), index_at(m, "elements")};
      if (mb.first_element < 0 || mb.elements < 1 || mb.first_element + mb.elements > int(s.elements.size()))
        throw std::out_of_range("member element range");
      s.members.push_back(mb);
    }
    for (const auto& d : j.at("supports")) {
      SupportRecord sp{d.at("node"), d.value("type", std::string()), d.at("series"), index_at(d, "node_index"),
                       d.value("fixed", std::vector<bool>(3 * (s.dimension - 1), false))};
      if (sp.node_index < 0 || sp.node_index >= int(s.nodes_m.size())) throw std::out_of_range("support node index");
      if (sp.fixed.size() != std::size_t(3 * (s.dimension - 1))) throw std::out_of_range("a support's fixed DOFs");
      s.supports.push_back(sp);
    }
    for (const ElementRecord& e : s.elements)
      if (e.member < 0 || e.member >= int(s.members.size())) throw std::out_of_range("element member index");
    s.gravity_m_s2 = j.value("gravity_m_s2", std::vector<double>(s.dimension, 0.0));
    if (s.gravity_m_s2.size() != std::size_t(s.dimension)) throw std::out_of_range("gravity_m_s2");
    s.plane_thickness_m = j.value("plane_thickness_m", 1.0);
    return s;
  } catch (const std::exception& e) {
    throw std::runtime_error(where + " is malformed (" + e.what() + ")");
  }
}


nlohmann::json face_profile_to_json(const FaceProfileRecord& f) {
  nlohmann::json bins = nlohmann::json::array();
  for (const FaceBin& b : f.bins)
    bins.push_back({{"member", b.member}, {"element", b.element}, {"from", b.from}, {"to", b.to}, {"height_from", b.height_from}, {"height_to", b.height_to}});
  return {{"members", f.members}, {"direction", f.direction}, {"width", f.width}, {"bins", bins},
          {"units", {{"from", "m"}, {"to", "m"}, {"height_from", "m"}, {"height_to", "m"}, {"width", "m"}}}};
}

FaceProfileRecord face_profile_from_json(const nlohmann::json& j, const std::string& where) {
  try {
    FaceProfileRecord f;
    f.members = j.at("members").get<std::vector<std::string>>();
    f.direction = j.at("direction").get<std::vector<double>>();
    if (f.direction.size() != 2 && f.direction.size() != 3) throw std::out_of_range("direction");
    f.width = j.at("width").get<double>();
    if (!j.at("bins").is_array()) throw std::out_of_range("bins is not an array");
    for (const auto& b : j.at("bins")) {
      const double from = b.at("from").get<double>(), to = b.at("to").get<double>();
      // A face written before heights were recorded stands vertical: its height is its span along the face.
      f.bins.push_back({b.at("member").get<std::string>(), index_at(b, "element"), from, to, b.value("height_from", from), b.value("height_to", to)});
    }
    return f;
  } catch (const std::exception& e) {
    throw std::runtime_error(where + " is malformed (" + std::string(e.what()) + ")");
  }
}

nlohmann::json solid_model_to_json(const SolidModel& m) {
  return {{"element", m.element}, {"cells", m.cells}, {"nodes", m.nodes}, {"elements", m.elements}, {"height_m", m.height_m},
          {"crest_thickness_m", m.crest_thickness_m}, {"base_thickness_m", m.base_thickness_m}, {"width_m", m.width_m},
          {"sloped_face", m.sloped_face}, {"youngs_modulus_Pa", m.youngs_modulus_Pa}, {"poisson_ratio", m.poisson_ratio},
          {"axes", m.axes}};
}

namespace {

SolidModel read_solid_model(const nlohmann::json& m) {
  SolidModel sm;
  sm.element = m.at("element").get<std::string>(), sm.sloped_face = m.value("sloped_face", std::string()), sm.axes = m.value("axes", std::string());
  sm.cells = m.at("cells").get<std::vector<int>>(), sm.nodes = index_at(m, "nodes"), sm.elements = index_at(m, "elements");
  sm.height_m = m.at("height_m"), sm.crest_thickness_m = m.at("crest_thickness_m"), sm.base_thickness_m = m.at("base_thickness_m");
  sm.width_m = m.at("width_m"), sm.youngs_modulus_Pa = m.at("youngs_modulus_Pa"), sm.poisson_ratio = m.at("poisson_ratio");
  return sm;
}

}  // namespace

SolidModel solid_model_from_json(const nlohmann::json& m, const std::string& where) {
  try {
    return read_solid_model(m);
  } catch (const std::exception& e) {
    throw std::runtime_error(where + " is malformed (" + std::string(e.what()) + ")");
  }
}

nlohmann::json solid_check_to_json(const SolidCheckRecord& c) {
  const nlohmann::json model = solid_model_to_json(c.model);
  nlohmann::json cases = nlohmann::json::array();
  for (const SolidCase& k : c.cases) {
    nlohmann::json e{{"name", k.name}, {"type", k.type}};
    if (k.time_s) e["time_s"] = *k.time_s;
    if (!k.member.empty()) e["member"] = k.member;
    if (k.profile) e["profile"] = {{"height_m", k.profile->height_m}, {"pressure_Pa", k.profile->pressure_Pa}};
    if (!k.note.empty()) e["note"] = k.note;
    e["load_resultant_N"] = k.load_resultant_N;
    nlohmann::json peaks = nlohmann::json::object();
    for (const auto& [measure, at] : k.peaks)
      for (const auto& [where, p] : at) peaks[measure][where] = {{"value_Pa", p.value_Pa}, {"location_m", p.location_m}};
    e["peaks"] = peaks;
    e["max_nodal_base_reaction_N"] = k.max_nodal_base_reaction_N;
    e["total_base_reaction_N"] = k.total_base_reaction_N;
    e["max_displacement_m"] = k.max_displacement_m;
    cases.push_back(e);
  }
  return {{"model", model}, {"cases", cases}};
}

SolidCheckRecord solid_check_from_json(const nlohmann::json& j, const std::string& where) {
  try {
    SolidCheckRecord c;
    c.model = read_solid_model(j.at("model"));
    if (!j.at("cases").is_array()) throw std::out_of_range("cases is not an array");
    for (const auto& e : j.at("cases")) {
      SolidCase k;
      k.name = e.at("name").get<std::string>(), k.type = e.at("type").get<std::string>();
      if (e.contains("time_s")) k.time_s = e.at("time_s").get<double>();
      k.member = e.value("member", std::string()), k.note = e.value("note", std::string());
      if (e.contains("profile"))
        k.profile = SolidProfile{e["profile"].at("height_m").get<std::vector<double>>(), e["profile"].at("pressure_Pa").get<std::vector<double>>()};
      k.load_resultant_N = e.at("load_resultant_N"), k.max_nodal_base_reaction_N = e.at("max_nodal_base_reaction_N");
      k.max_displacement_m = e.at("max_displacement_m"), k.total_base_reaction_N = e.at("total_base_reaction_N").get<std::vector<double>>();
      for (const auto& [measure, at] : e.at("peaks").items())
        for (const auto& [place, p] : at.items()) {
          SolidPeak pk{p.at("value_Pa").get<double>(), p.at("location_m").get<std::vector<double>>()};
          if (pk.location_m.size() != 2 && pk.location_m.size() != 3) throw std::out_of_range("a peak's location");
          k.peaks[measure][place] = pk;
        }
      for (const char* measure : {"von_mises", "max_principal", "min_principal"})
        if (!k.peaks[measure].count("gauss")) throw std::out_of_range("case '" + k.name + "' has no " + measure + " peak at the Gauss points");
      c.cases.push_back(std::move(k));
    }
    return c;
  } catch (const std::exception& e) {
    throw std::runtime_error(where + " is malformed (" + std::string(e.what()) + ")");
  }
}

nlohmann::json solid_field_to_json(const SolidFieldRecord& f) {
  nlohmann::json cases = nlohmann::json::array();
  for (const SolidFieldCase& c : f.cases)
    cases.push_back({{"name", c.name}, {"von_mises_Pa", c.von_mises_Pa}, {"max_principal_Pa", c.max_principal_Pa}, {"displacement_m", c.displacement_m}});
  return {{"dim", f.dim}, {"nodes_per_element", f.nodes_per_element}, {"axes", f.axes}, {"nodes_m", f.nodes_m}, {"elements", f.elements},
          {"cases", cases}};
}

SolidFieldRecord solid_field_from_json(const nlohmann::json& j, const std::string& where) {
  auto finite = [](const std::vector<double>& v) {
    for (double x : v)
      if (!std::isfinite(x)) return false;
    return true;
  };
  try {
    SolidFieldRecord f;
    f.dim = j.at("dim").get<int>(), f.nodes_per_element = j.at("nodes_per_element").get<int>();
    if (!((f.dim == 3 && f.nodes_per_element == 8) || (f.dim == 2 && f.nodes_per_element == 4)))
      throw std::out_of_range("dim and nodes_per_element do not match");
    f.axes = j.value("axes", std::string());
    f.nodes_m = j.at("nodes_m").get<std::vector<double>>();
    if (f.nodes_m.empty() || f.nodes_m.size() % f.dim || !finite(f.nodes_m)) throw std::out_of_range("nodes_m");
    f.elements = j.at("elements").get<std::vector<long>>();
    if (f.elements.empty() || f.elements.size() % f.nodes_per_element) throw std::out_of_range("elements");
    for (long id : f.elements)
      if (id < 0 || id >= static_cast<long>(f.nodes())) throw std::out_of_range("elements refers to a node that does not exist");
    for (const auto& c : j.at("cases")) {
      SolidFieldCase k{c.value("name", std::string()), c.at("von_mises_Pa").get<std::vector<double>>(),
                       c.at("max_principal_Pa").get<std::vector<double>>(), c.value("displacement_m", std::vector<double>())};
      if (k.von_mises_Pa.size() != f.nodes() || k.max_principal_Pa.size() != f.nodes() || !finite(k.von_mises_Pa) || !finite(k.max_principal_Pa))
        throw std::out_of_range("case '" + k.name + "': a stress per node, finite");
      f.cases.push_back(std::move(k));
    }
    if (f.cases.empty()) throw std::out_of_range("no cases");
    return f;
  } catch (const std::exception& e) {
    throw std::runtime_error(where + " is malformed (" + std::string(e.what()) + ")");
  }
}

}  // namespace dmi
