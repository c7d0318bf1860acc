#include "engine/io/peak_contact_json.hpp"

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
    for (const auto& l : j.at("loads"))
      p.loads.push_back({l.at("member").get<std::string>(), l.at("position").get<double>(), l.at("point").get<std::vector<double>>(),
                         l.at("force").get<std::vector<double>>()});
    return p;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(where + " is malformed (" + std::string(e.what()) + ")");
  }
}

}  // namespace dmi
