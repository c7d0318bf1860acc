// Two models or two designs side by side, as typed records: the with / without buffer comparison of a comparison pair
// and the plane model beside its 3D model (compare_3d). Built by design (document.cpp), written to design.json by
// to_json, read back validated by from_json for the report and `check`'s summary (docs/design-json.md).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dmi::design {

// design.json "comparison": every compared peak, with and without the buffer, and the reduction
// 100 (without - with) / without in % (none when the bare value is 0).
struct BufferComparison {
  struct Quantity {
    std::string id, title, unit;
    double with_buffer = 0, without_buffer = 0;
    std::optional<double> reduction_percent;
  };
  std::vector<Quantity> quantities;
  std::string note;
};

// design.json "plane_and_space": per 3D run, the plane run it stands beside, their verdicts and governing numbers, and
// ratio = plane / 3D (none when the 3D value is 0).
struct PlaneAndSpace {
  struct Quantity {
    std::string id, title, unit;
    double plane = 0, space = 0;
    std::optional<double> ratio;
  };
  struct Pair {
    std::string variant;
    std::optional<bool> plane_passed, space_passed;
    std::vector<Quantity> quantities;
  };
  std::vector<Pair> pairs;
  std::string note;
};

nlohmann::json to_json(const BufferComparison& c);
nlohmann::json to_json(const PlaneAndSpace& p);
// `where` names the document in errors; the section absent (null) reads as nullopt.
std::optional<BufferComparison> comparison_from_json(const nlohmann::json& j, const std::string& where);
std::optional<PlaneAndSpace> plane_and_space_from_json(const nlohmann::json& j, const std::string& where);

}  // namespace dmi::design
