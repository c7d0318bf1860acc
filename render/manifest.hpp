// The pictures of a run folder as a typed record: each picture's file (and the SVG of a chart), kind, run, caption and
// size, a field picture's colour ranges and deformation scale; written as OUT/images/images.json (to_json), read by
// the report in memory.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace dmi::render {

struct Picture {
  std::string file, kind, variant, caption;  // kind: field_governing | field_section | field_sequence | field_solid | field_comparison | chart
  int width = 0, height = 0;
  std::optional<std::string> vector_file;  // a chart's SVG beside its PNG
  struct Field {
    double particles_lo_Pa = 0, particles_hi_Pa = 0, members_lo_Pa = 0, members_hi_Pa = 0;
    double deform_scale = 0;  // the members' centre line drawn deformed by this factor (0: not)
    std::string quantity;
  };
  std::optional<Field> field;  // field pictures: the colour scales
};

struct Manifest {
  std::vector<Picture> images;
  std::string quantity;
  double render_seconds = 0;
  int processes = 1;
  std::optional<std::string> error;  // why the report has no pictures
};

nlohmann::json to_json(const Manifest& m);

}  // namespace dmi::render
