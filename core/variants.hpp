// The names of a preset scenario's variants (its runs), shared by the scenario reader that makes them and the design
// layer that pairs them: "" alone; "with_buffer" and "without_buffer" (compare: with_and_without_buffer); each
// followed by its 3D model's variant with compare_3d, the name plus "_3d" ("3d" alone for "").
#pragma once
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace dmi {

inline constexpr const char* kSpaceSuffix = "_3d";

// Whether a variant is the 3D model of compare_3d.
inline bool is_space_variant(const std::string& variant) {
  const std::string s = kSpaceSuffix;
  return variant == s.substr(1) || (variant.size() > s.size() && variant.compare(variant.size() - s.size(), s.size(), s) == 0);
}

// The plane variant a 3D one stands beside ("with_buffer_3d" -> "with_buffer", "3d" -> ""); a plane variant itself.
inline std::string plane_variant(const std::string& variant) {
  if (!is_space_variant(variant)) return variant;
  const std::string s = kSpaceSuffix;
  return variant == s.substr(1) ? std::string() : variant.substr(0, variant.size() - s.size());
}

// The 3D variant beside a plane one ("" -> "3d").
inline std::string space_variant(const std::string& plane) { return plane.empty() ? std::string(kSpaceSuffix).substr(1) : plane + kSpaceSuffix; }

// The results files of an output folder with their variants: OUT/results.h5 (""), or OUT/with_buffer/ and
// OUT/without_buffer/ both holding one; then the 3D models of compare_3d beside them (OUT/3d/, OUT/<variant>_3d/).
// Empty when the folder holds neither.
inline std::vector<std::pair<std::string, std::filesystem::path>> variant_results(const std::filesystem::path& d) {
  namespace fs = std::filesystem;
  std::vector<std::pair<std::string, fs::path>> files;
  if (fs::exists(d / "results.h5")) files.push_back({"", d / "results.h5"});
  else if (fs::exists(d / "with_buffer" / "results.h5") && fs::exists(d / "without_buffer" / "results.h5"))
    files = {{"with_buffer", d / "with_buffer" / "results.h5"}, {"without_buffer", d / "without_buffer" / "results.h5"}};
  for (std::size_t k = 0, n = files.size(); k < n; ++k)
    if (const std::string v = space_variant(files[k].first); fs::exists(d / v / "results.h5")) files.push_back({v, d / v / "results.h5"});
  return files;
}

}  // namespace dmi
