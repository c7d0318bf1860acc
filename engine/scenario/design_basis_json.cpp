#include "engine/scenario/design_basis_json.hpp"

#include <set>

#include "engine/common/error.hpp"

namespace dmi {

using nlohmann::json;

namespace {

void put(json& o, const char* key, double v) {
  if (is_set(v)) o[key] = v;
}

const char* dam_type_name(DamKind k) { return k == DamKind::steel_open ? "steel_open" : "concrete_gravity"; }
const char* boulder_model_name(BoulderModel m) {
  return m == BoulderModel::rigid ? "rigid" : m == BoulderModel::elastic_when_touching ? "elastic_when_touching" : "elastic";
}

// One object of the basis: its keys checked against those it may hold, numbers by range.
class Object {
 public:
  Object(const json& j, std::string file, std::string path, std::set<std::string> keys)
      : j_(j), file_(std::move(file)), path_(std::move(path)), keys_(std::move(keys)) {
    if (!j_.is_object()) fail(path_, j_, "an object");
    for (const auto& [k, v] : j_.items())
      if (!keys_.count(k)) fail(path_ + "/" + k, v, "one of the keys of docs/design-json.md (design basis)");
  }
  bool has(const char* key) const { return j_.contains(key); }
  // A number > 0 (or >= 0 with zero_ok); optional ones stay unset when absent.
  double positive(const char* key, bool required = true, bool zero_ok = false) const {
    if (!has(key)) {
      if (required) fail(path_ + "/" + key, json(), std::string("a number ") + (zero_ok ? ">= 0" : "> 0") + " (missing)");
      return kUnset;
    }
    const json& v = j_[key];
    if (!v.is_number() || !std::isfinite(v.get<double>()) || (zero_ok ? v.get<double>() < 0 : !(v.get<double>() > 0)))
      fail(path_ + "/" + key, v, std::string("a number ") + (zero_ok ? ">= 0" : "> 0"));
    return v.get<double>();
  }
  double poisson(const char* key) const {  // optional; in (-1, 0.5)
    if (!has(key)) return kUnset;
    const json& v = j_[key];
    if (!v.is_number() || !(v.get<double>() > -1 && v.get<double>() < 0.5)) fail(path_ + "/" + key, v, "a number in (-1, 0.5)");
    return v.get<double>();
  }
  double number(const char* key) const {  // any finite number, optional
    if (!has(key)) return kUnset;
    const json& v = j_[key];
    if (!v.is_number() || !std::isfinite(v.get<double>())) fail(path_ + "/" + key, v, "a finite number");
    return v.get<double>();
  }
  std::string text(const char* key, const std::set<std::string>& allowed) const {
    if (!has(key) || !j_[key].is_string() || (!allowed.empty() && !allowed.count(j_[key].get<std::string>()))) {
      std::string list;
      for (const auto& a : allowed) list += (list.empty() ? "" : " | ") + a;
      fail(path_ + "/" + key, has(key) ? j_[key] : json(), allowed.empty() ? "a string" : "one of " + list);
    }
    return j_[key];
  }
  const json& at(const char* key) const { return j_[key]; }
  const std::string& path() const { return path_; }
  [[noreturn]] void fail(const std::string& path, const json& v, const std::string& expected) const {
    throw InputError(file_, path, v.is_null() ? "" : v.dump(), expected);
  }

 private:
  const json& j_;
  std::string file_, path_;
  std::set<std::string> keys_;
};

DamBasis read_dam(const Object& o) {
  DamBasis d;
  d.type = o.text("type", {"concrete_gravity", "steel_open"}) == "steel_open" ? DamKind::steel_open : DamKind::concrete_gravity;
  d.height_m = o.positive("height_m"), d.width_m = o.positive("width_m");
  if (o.has("width_rule")) d.width_rule = o.text("width_rule", {});
  d.youngs_modulus_Pa = o.positive("youngs_modulus_Pa"), d.poisson_ratio = o.poisson("poisson_ratio");
  d.density_kg_m3 = o.positive("density_kg_m3");
  const bool concrete = d.type == DamKind::concrete_gravity;
  d.crest_thickness_m = o.positive("crest_thickness_m", concrete), d.base_thickness_m = o.positive("base_thickness_m", concrete);
  d.heel_x_m = o.number("heel_x_m"), d.toe_x_m = o.number("toe_x_m");
  d.crest_upstream_x_m = o.number("crest_upstream_x_m"), d.crest_downstream_x_m = o.number("crest_downstream_x_m");
  d.deposit_height_m = o.positive("deposit_height_m", false), d.deposit_unit_weight_N_m3 = o.positive("deposit_unit_weight_N_m3", false);
  d.deposit_coefficient = o.positive("deposit_coefficient", false, true);
  if (o.has("deposit_submerged")) d.deposit_submerged = o.text("deposit_submerged", {"yes", "no"}) == "yes";
  d.water_height_m = o.positive("water_height_m", false), d.water_unit_weight_N_m3 = o.positive("water_unit_weight_N_m3", false);
  // Groups that mean something only together.
  auto together = [&](std::initializer_list<std::pair<const char*, double>> group) {
    int set = 0;
    for (const auto& [k, v] : group) set += is_set(v);
    if (set == 0 || set == static_cast<int>(group.size())) return;
    for (const auto& [k, v] : group)
      if (!is_set(v)) o.fail(o.path() + "/" + k, json(), "a number (missing; it goes with the others of its group)");
  };
  together({{"heel_x_m", d.heel_x_m}, {"toe_x_m", d.toe_x_m}, {"crest_upstream_x_m", d.crest_upstream_x_m}, {"crest_downstream_x_m", d.crest_downstream_x_m}});
  together({{"deposit_height_m", d.deposit_height_m}, {"deposit_unit_weight_N_m3", d.deposit_unit_weight_N_m3}, {"deposit_coefficient", d.deposit_coefficient}});
  together({{"water_height_m", d.water_height_m}, {"water_unit_weight_N_m3", d.water_unit_weight_N_m3}});
  d.column_diameter_m = o.positive("column_diameter_m", !concrete), d.column_wall_thickness_m = o.positive("column_wall_thickness_m", !concrete);
  d.yield_strength_Pa = o.positive("yield_strength_Pa", false);
  if (o.has("member_model")) d.member_model = o.text("member_model", {"plastic", "elastic"});
  return d;
}

BoulderBasis read_boulder(const Object& o) {
  BoulderBasis b;
  b.mass_kg = o.positive("mass_kg"), b.diameter_m = o.positive("diameter_m"), b.density_kg_m3 = o.positive("density_kg_m3");
  b.youngs_modulus_Pa = o.positive("youngs_modulus_Pa"), b.poisson_ratio = o.poisson("poisson_ratio");
  b.speed_m_s = o.positive("speed_m_s"), b.impact_height_m = o.positive("impact_height_m");
  if (o.has("model")) {
    const std::string m = o.text("model", {"elastic", "rigid", "elastic_when_touching"});
    b.model = m == "rigid" ? BoulderModel::rigid : m == "elastic_when_touching" ? BoulderModel::elastic_when_touching : BoulderModel::elastic;
  }
  return b;
}

DebrisBasis read_debris(const Object& o, const std::string& file) {
  DebrisBasis d;
  d.density_kg_m3 = o.positive("density_kg_m3"), d.depth_m = o.positive("depth_m"), d.length_m = o.positive("length_m", false);
  d.speed_m_s = o.positive("speed_m_s"), d.channel_slope_deg = o.positive("channel_slope_deg", false, true);
  d.front_length_m = o.positive("front_length_m", false, true);
  d.youngs_modulus_Pa = o.positive("youngs_modulus_Pa", false), d.poisson_ratio = o.poisson("poisson_ratio");
  d.bulk_modulus_Pa = o.positive("bulk_modulus_Pa", false);
  if (o.has("hydrograph")) {
    const Object g(o.at("hydrograph"), file, o.path() + "/hydrograph",
                   {"source", "duration_s", "volume_m3_per_m", "mass_kg_per_m", "peak_flux_time_s", "section_distance_m"});
    HydrographBasis h;
    h.source = g.text("source", {});
    h.duration_s = g.positive("duration_s"), h.volume_m3_per_m = g.positive("volume_m3_per_m"), h.mass_kg_per_m = g.positive("mass_kg_per_m");
    h.peak_flux_time_s = g.positive("peak_flux_time_s", true, true), h.section_distance_m = g.positive("section_distance_m");
    d.hydrograph = h;
  }
  return d;
}

BufferBasis read_buffer(const Object& o) {
  BufferBasis b;
  if (o.has("type")) b.type = o.text("type", {});
  b.youngs_modulus_Pa = o.positive("youngs_modulus_Pa"), b.poisson_ratio = o.poisson("poisson_ratio");
  b.thickness_m = o.positive("thickness_m"), b.bottom_m = o.positive("bottom_m", false, true), b.top_m = o.positive("top_m", false);
  b.friction_angle_deg = o.positive("friction_angle_deg", false);
  return b;
}

}  // namespace

json design_basis_to_json(const DesignBasis& b) {
  const DamBasis& d = b.dam;
  json dam{{"type", dam_type_name(d.type)}};
  if (!d.width_rule.empty() && d.width_rule != "given") dam["width_rule"] = d.width_rule;
  put(dam, "height_m", d.height_m), put(dam, "width_m", d.width_m), put(dam, "youngs_modulus_Pa", d.youngs_modulus_Pa);
  put(dam, "poisson_ratio", d.poisson_ratio), put(dam, "density_kg_m3", d.density_kg_m3);
  put(dam, "crest_thickness_m", d.crest_thickness_m), put(dam, "base_thickness_m", d.base_thickness_m);
  put(dam, "heel_x_m", d.heel_x_m), put(dam, "toe_x_m", d.toe_x_m);
  put(dam, "crest_upstream_x_m", d.crest_upstream_x_m), put(dam, "crest_downstream_x_m", d.crest_downstream_x_m);
  put(dam, "deposit_height_m", d.deposit_height_m), put(dam, "deposit_unit_weight_N_m3", d.deposit_unit_weight_N_m3);
  put(dam, "deposit_coefficient", d.deposit_coefficient);
  if (d.deposit_submerged) dam["deposit_submerged"] = "yes";
  put(dam, "water_height_m", d.water_height_m), put(dam, "water_unit_weight_N_m3", d.water_unit_weight_N_m3);
  put(dam, "column_diameter_m", d.column_diameter_m), put(dam, "column_wall_thickness_m", d.column_wall_thickness_m);
  put(dam, "yield_strength_Pa", d.yield_strength_Pa);
  if (!d.member_model.empty()) dam["member_model"] = d.member_model;
  json out{{"dam", dam}};
  if (const auto& k = b.boulder) {
    json o{{"model", boulder_model_name(k->model)}};
    put(o, "mass_kg", k->mass_kg), put(o, "diameter_m", k->diameter_m), put(o, "density_kg_m3", k->density_kg_m3);
    put(o, "youngs_modulus_Pa", k->youngs_modulus_Pa), put(o, "poisson_ratio", k->poisson_ratio);
    put(o, "speed_m_s", k->speed_m_s), put(o, "impact_height_m", k->impact_height_m);
    out["boulder"] = o;
  }
  if (const auto& f = b.debris) {
    json o = json::object();
    put(o, "density_kg_m3", f->density_kg_m3), put(o, "depth_m", f->depth_m), put(o, "length_m", f->length_m);
    put(o, "speed_m_s", f->speed_m_s), put(o, "channel_slope_deg", f->channel_slope_deg), put(o, "front_length_m", f->front_length_m);
    put(o, "youngs_modulus_Pa", f->youngs_modulus_Pa), put(o, "poisson_ratio", f->poisson_ratio), put(o, "bulk_modulus_Pa", f->bulk_modulus_Pa);
    if (const auto& g = f->hydrograph) {
      json h{{"source", g->source}};
      put(h, "duration_s", g->duration_s), put(h, "volume_m3_per_m", g->volume_m3_per_m), put(h, "mass_kg_per_m", g->mass_kg_per_m);
      put(h, "peak_flux_time_s", g->peak_flux_time_s), put(h, "section_distance_m", g->section_distance_m);
      o["hydrograph"] = h;
    }
    out["debris_surge"] = o;
  }
  if (const auto& t = b.buffer) {
    json o{{"type", t->type}};
    put(o, "youngs_modulus_Pa", t->youngs_modulus_Pa), put(o, "poisson_ratio", t->poisson_ratio), put(o, "thickness_m", t->thickness_m);
    put(o, "bottom_m", t->bottom_m), put(o, "top_m", t->top_m), put(o, "friction_angle_deg", t->friction_angle_deg);
    out["tyre_buffer"] = o;
  }
  return out;
}

DesignBasis design_basis_from_json(const json& j, const std::string& file, const std::string& prefix) {
  const Object top(j, file, prefix, {"dam", "boulder", "debris_surge", "tyre_buffer"});
  if (!top.has("dam")) top.fail(prefix + "/dam", json(), "an object (missing)");
  DesignBasis b;
  b.dam = read_dam(Object(j["dam"], file, prefix + "/dam",
                          {"type", "height_m", "width_m", "width_rule", "youngs_modulus_Pa", "poisson_ratio", "density_kg_m3", "crest_thickness_m",
                           "base_thickness_m", "heel_x_m", "toe_x_m", "crest_upstream_x_m", "crest_downstream_x_m", "deposit_height_m", "deposit_unit_weight_N_m3", "deposit_coefficient",
                           "deposit_submerged", "water_height_m", "water_unit_weight_N_m3", "column_diameter_m", "column_wall_thickness_m",
                           "yield_strength_Pa", "member_model"}));
  if (top.has("boulder"))
    b.boulder = read_boulder(Object(j["boulder"], file, prefix + "/boulder",
                                    {"mass_kg", "diameter_m", "density_kg_m3", "youngs_modulus_Pa", "poisson_ratio", "speed_m_s",
                                     "impact_height_m", "model"}));
  if (top.has("debris_surge"))
    b.debris = read_debris(Object(j["debris_surge"], file, prefix + "/debris_surge",
                                  {"density_kg_m3", "depth_m", "length_m", "speed_m_s", "channel_slope_deg", "front_length_m",
                                   "youngs_modulus_Pa", "poisson_ratio", "bulk_modulus_Pa", "hydrograph"}),
                           file);
  if (top.has("tyre_buffer"))
    b.buffer = read_buffer(Object(j["tyre_buffer"], file, prefix + "/tyre_buffer",
                                  {"type", "youngs_modulus_Pa", "poisson_ratio", "thickness_m", "bottom_m", "top_m", "friction_angle_deg"}));
  return b;
}

}  // namespace dmi
