#include "design/members_json.hpp"

#include "design/record_reader.hpp"

#include <stdexcept>

namespace dmi::design {

using nlohmann::json;

namespace {

json extreme(const Extreme& e) { return e.set ? json{{"value", e.value}, {"time_s", e.time}} : json(nullptr); }

json location(const Station& s, int dim) { return dim == 3 ? json{s.x, s.y, s.z} : json{s.x, s.y}; }

// The member-wide peak of one station quantity: the station and instant where it is largest (or smallest).
json member_peak(const MemberEnvelope& m, Extreme Station::*q, bool smallest, const char* unit) {
  const Station* best = nullptr;
  for (const auto& st : m.stations) {
    const Extreme& e = st.*q;
    if (!e.set) continue;
    if (!best || (smallest ? e.value < (best->*q).value : e.value > (best->*q).value)) best = &st;
  }
  if (!best) return nullptr;
  return json{{"value", (best->*q).value}, {"unit", unit}, {"time_s", (best->*q).time}, {"position", best->position}, {"s_m", best->s_m},
              {"location_m", location(*best, m.dim)}};
}

}  // namespace

json extreme_json(const Extreme& e) { return extreme(e); }

json member_json(const MemberEnvelope& m) {
  const bool space = m.dim == 3;
  json stations = json::array();
  for (const auto& s : m.stations) {
    json j{{"position", s.position}, {"s_m", s.s_m}, {"location_m", location(s, m.dim)}, {"depth_m", s.depth},
           {"N_max_N", extreme(s.N_max)}, {"N_min_N", extreme(s.N_min)}, {"V_abs_max_N", extreme(s.V_abs)},
           {"M_max_Nm", extreme(s.M_max)}, {"M_min_Nm", extreme(s.M_min)},
           {"sigma_tension_max_Pa", extreme(s.sigma_tension)}, {"sigma_compression_min_Pa", extreme(s.sigma_compression)},
           {"tau_max_Pa", extreme(s.tau)}, {"von_mises_max_Pa", extreme(s.von_mises)}};
    if (space) {  // V and M above are the resultants |(Vy, Vz)|, |(My, Mz)|
      j["Vy_abs_max_N"] = extreme(s.Vy_abs), j["Vz_abs_max_N"] = extreme(s.Vz_abs), j["T_abs_max_Nm"] = extreme(s.T_abs);
      j["My_max_Nm"] = extreme(s.My_max), j["My_min_Nm"] = extreme(s.My_min), j["Mz_max_Nm"] = extreme(s.Mz_max), j["Mz_min_Nm"] = extreme(s.Mz_min);
      j["principal_max_Pa"] = extreme(s.principal);
    }
    stations.push_back(j);
  }
  json peaks{{"N_max", member_peak(m, &Station::N_max, false, "N")},
             {"N_min", member_peak(m, &Station::N_min, true, "N")},
             {"V_abs_max", member_peak(m, &Station::V_abs, false, "N")},
             {"M_max", member_peak(m, &Station::M_max, false, "N m")},
             {"M_min", member_peak(m, &Station::M_min, true, "N m")},
             {"sigma_tension_max", member_peak(m, &Station::sigma_tension, false, "Pa")},
             {"sigma_compression_min", member_peak(m, &Station::sigma_compression, true, "Pa")},
             {"tau_max", member_peak(m, &Station::tau, false, "Pa")},
             {"von_mises_max", member_peak(m, &Station::von_mises, false, "Pa")}};
  if (space) {
    peaks["T_abs_max"] = member_peak(m, &Station::T_abs, false, "N m");
    peaks["principal_max"] = member_peak(m, &Station::principal, false, "Pa");
  }
  json out{{"name", m.name}, {"material", m.cls}, {"length_m", m.length}, {"peaks", peaks}, {"stations", stations}};
  if (space) out["resultants"] = "V = |(Vy, Vz)|, M = |(My, Mz)| (M_min not defined); local axes of the section (docs/design-checks.md)";
  return out;
}

Extreme extreme_from_json(const json& j, const char* key, const std::string& where) {
  Extreme e;
  if (!j.contains(key) || j[key].is_null()) return e;
  const json& x = j[key];
  if (!x.is_object() || !x.contains("value") || !x["value"].is_number() || !x.contains("time_s") || !x["time_s"].is_number())
    throw std::runtime_error(where + "." + key + " is neither null nor {value, time_s}");
  e.value = x["value"], e.time = x["time_s"], e.set = true;
  return e;
}

using record::number;

MemberEnvelope member_from_json(const json& j, int dim, const std::string& where) {
  MemberEnvelope m;
  m.dim = dim;
  if (!j.is_object() || !j.contains("name") || !j["name"].is_string() || !j.contains("material") || !j["material"].is_string())
    throw std::runtime_error(where + " has no name or material");
  m.name = j["name"], m.cls = j["material"], m.length = number(j, "length_m", where);
  if (!j.contains("stations") || !j["stations"].is_array()) throw std::runtime_error(where + ".stations is not an array");
  for (std::size_t k = 0; k < j["stations"].size(); ++k) {
    const json& s = j["stations"][k];
    const std::string at = where + ".stations[" + std::to_string(k) + "]";
    Station st;
    st.position = number(s, "position", at), st.s_m = number(s, "s_m", at), st.depth = number(s, "depth_m", at);
    const json& loc = s.contains("location_m") ? s["location_m"] : json();
    if (!loc.is_array() || loc.size() != static_cast<std::size_t>(dim) || !loc[0].is_number() || !loc[1].is_number() || (dim == 3 && !loc[2].is_number()))
      throw std::runtime_error(at + ".location_m is not " + std::to_string(dim) + " numbers");
    st.x = loc[0], st.y = loc[1], st.z = dim == 3 ? loc[2].get<double>() : 0.0;
    const std::pair<const char*, Extreme Station::*> fields[] = {
        {"N_max_N", &Station::N_max}, {"N_min_N", &Station::N_min}, {"V_abs_max_N", &Station::V_abs}, {"M_max_Nm", &Station::M_max},
        {"M_min_Nm", &Station::M_min}, {"sigma_tension_max_Pa", &Station::sigma_tension}, {"sigma_compression_min_Pa", &Station::sigma_compression},
        {"tau_max_Pa", &Station::tau}, {"von_mises_max_Pa", &Station::von_mises}, {"Vy_abs_max_N", &Station::Vy_abs},
        {"Vz_abs_max_N", &Station::Vz_abs}, {"T_abs_max_Nm", &Station::T_abs}, {"My_max_Nm", &Station::My_max}, {"My_min_Nm", &Station::My_min},
        {"Mz_max_Nm", &Station::Mz_max}, {"Mz_min_Nm", &Station::Mz_min}, {"principal_max_Pa", &Station::principal}};
    for (const auto& [key, field] : fields) st.*field = extreme_from_json(s, key, at);
    m.stations.push_back(st);
  }
  return m;
}

std::vector<MemberEnvelope> members_from_json(const json& run, const std::string& where) {
  std::vector<MemberEnvelope> out;
  const json& list = run.is_object() && run.contains("members") ? run["members"] : json::array();
  if (!list.is_array()) throw std::runtime_error(where + ".members is not an array");
  const int dim = run.value("dimension", 2);
  for (std::size_t k = 0; k < list.size(); ++k) out.push_back(member_from_json(list[k], dim, where + ".members[" + std::to_string(k) + "]"));
  return out;
}

}  // namespace dmi::design
