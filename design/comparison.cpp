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
  c.quantities = record::items<BufferComparison::Quantity>(list(j, "quantities", where), where + ".quantities", [](const json& q, const std::string& at) {
    return BufferComparison::Quantity{text(q, "id", at), text(q, "title", at), text(q, "unit", at), number(q, "with_buffer", at),
                                      number(q, "without_buffer", at), number_or_none(q, "reduction_percent", at)};
  });
  return c;
}

std::optional<PlaneAndSpace> plane_and_space_from_json(const json& j, const std::string& where) {
  if (j.is_null()) return std::nullopt;
  PlaneAndSpace p;
  p.note = text(j, "note", where);
  const auto quantity = [](const json& q, const std::string& at) {
    return PlaneAndSpace::Quantity{text(q, "id", at), text(q, "title", at), text(q, "unit", at), number(q, "plane", at), number(q, "space", at),
                                   number_or_none(q, "ratio", at)};
  };
  p.pairs = record::items<PlaneAndSpace::Pair>(list(j, "pairs", where), where + ".pairs", [&](const json& pair, const std::string& at) {
    return PlaneAndSpace::Pair{text(pair, "variant", at), flag_or_none(pair, "plane_passed", at), flag_or_none(pair, "space_passed", at),
                               record::items<PlaneAndSpace::Quantity>(list(pair, "quantities", at), at + ".quantities", quantity)};
  });
  return p;
}

}  // namespace dmi::design
