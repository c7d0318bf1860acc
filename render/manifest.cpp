#include "render/manifest.hpp"

namespace dmi::render {

nlohmann::json to_json(const Manifest& m) {
  nlohmann::json images = nlohmann::json::array();
  for (const Picture& p : m.images) {
    nlohmann::json e{{"file", p.file}, {"kind", p.kind}, {"variant", p.variant}, {"caption", p.caption}, {"width", p.width}, {"height", p.height}};
    if (const auto& f = p.field) {
      e["particles_range_Pa"] = {f->particles_lo_Pa, f->particles_hi_Pa};
      e["members_range_Pa"] = {f->members_lo_Pa, f->members_hi_Pa};
      e["deform_scale"] = f->deform_scale;
      e["quantity"] = f->quantity;
    }
    if (p.vector_file) e["vector_file"] = *p.vector_file;
    images.push_back(e);
  }
  nlohmann::json j{{"images", images}, {"quantity", m.quantity}, {"render_seconds", m.render_seconds}, {"processes", m.processes}};
  if (m.error) j["error"] = *m.error;
  return j;
}

}  // namespace dmi::render
