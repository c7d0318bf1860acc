#include "design/comparison.hpp"

#include "design/record_reader.hpp"

#include <stdexcept>

namespace dmi::design {

using nlohmann::json;

using namespace record;

namespace {

json optional_json(const std::optional<double>& x) { return x ? json(*x) : json(nullptr); }
json optional_json(const std::optional<bool>& x) { return x ? json(*x) : json(nullptr); }

}  // namespace

json to_json(const BufferComparison& c) {
  json rows = json::array();
  for (const auto& q : c.quantities)
    rows.push_back({{"id", q.id}, {"title", q.title}, {"unit", q.unit}, {"with_buffer", q.with_buffer}, {"without_buffer", q.without_buffer},
                    {"reduction_percent", optional_json(q.reduction_percent)}});
  return json{{"quantities", rows}, {"note", c.note}};
}

json to_json(const PlaneAndSpace& p) {
  json pairs = json::array();
  for (const auto& pair : p.pairs) {
    json rows = json::array();
    for (const auto& q : pair.quantities)
      rows.push_back({{"id", q.id}, {"title", q.title}, {"unit", q.unit}, {"plane", q.plane}, {"space", q.space}, {"ratio", optional_json(q.ratio)}});
    pairs.push_back({{"variant", pair.variant}, {"plane_passed", optional_json(pair.plane_passed)}, {"space_passed", optional_json(pair.space_passed)},
                     {"quantities", rows}});
  }
  return json{{"pairs", pairs}, {"note", p.note}};
}

std::optional<BufferComparison> comparison_from_json(const json& j, const std::string& where) {
  if (j.is_null()) return std::nullopt;
  BufferComparison c;
  c.note = text(j, "note", where);
  const json& rows = list(j, "quantities", where);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const std::string at = where + ".quantities[" + std::to_string(k) + "]";
    c.quantities.push_back({text(rows[k], "id", at), text(rows[k], "title", at), text(rows[k], "unit", at), number(rows[k], "with_buffer", at),
                            number(rows[k], "without_buffer", at), number_or_none(rows[k], "reduction_percent", at)});
  }
  return c;
}

std::optional<PlaneAndSpace> plane_and_space_from_json(const json& j, const std::string& where) {
  if (j.is_null()) return std::nullopt;
  PlaneAndSpace p;
  p.note = text(j, "note", where);
  const json& pairs = list(j, "pairs", where);
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const std::string at = where + ".pairs[" + std::to_string(k) + "]";
    PlaneAndSpace::Pair pair{text(pairs[k], "variant", at), flag_or_none(pairs[k], "plane_passed", at), flag_or_none(pairs[k], "space_passed", at), {}};
    const json& rows = list(pairs[k], "quantities", at);
    for (std::size_t n = 0; n < rows.size(); ++n) {
      const std::string q = at + ".quantities[" + std::to_string(n) + "]";
      pair.quantities.push_back({text(rows[n], "id", q), text(rows[n], "title", q), text(rows[n], "unit", q), number(rows[n], "plane", q),
                                 number(rows[n], "space", q), number_or_none(rows[n], "ratio", q)});
    }
    p.pairs.push_back(pair);
  }
  return p;
}

}  // namespace dmi::design
