#include "engine/scenario/identity.hpp"

#include <nlohmann/json.hpp>

#include "engine/scenario/sha256.hpp"

namespace dmi {

std::string scenario_identity(const std::string& source_text, const std::string& expanded_text, const std::string& variant) {
  const std::string& low_level = expanded_text.empty() ? source_text : expanded_text;
  const nlohmann::json j = nlohmann::json::parse(low_level, nullptr, false);  // a scenario built in code has no text
  return sha256_hex((j.is_discarded() ? low_level : j.dump()) + '\n' + variant);
}

}  // namespace dmi
