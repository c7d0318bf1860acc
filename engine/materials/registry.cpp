#include <stdexcept>

#include "engine/materials/material.hpp"
#include "engine/materials/viscous_fluid.hpp"

namespace dmi {

template <int D> std::unique_ptr<Material<D>> make_linear_elastic(const MaterialConfig&, Plane);
template <int D> std::unique_ptr<Material<D>> make_neo_hookean(const MaterialConfig&, Plane);
template <int D> std::unique_ptr<Material<D>> make_drucker_prager(const MaterialConfig&, Plane);

template <int D> std::unique_ptr<Material<D>> MaterialRegistry<D>::make(const MaterialConfig& c, Plane plane) const {
  auto it = factories_.find(c.model);
  if (it == factories_.end()) throw std::invalid_argument("unknown material model '" + c.model + "'");
  return it->second(c, plane);
}

template <int D> void register_materials(MaterialRegistry<D>& r) {
  r.add("linear_elastic", make_linear_elastic<D>);
  r.add("neo_hookean", make_neo_hookean<D>);
  r.add("drucker_prager", make_drucker_prager<D>);
  r.add("mu_i", make_drucker_prager<D>);
  r.add("newtonian", make_viscous_fluid<D>);
  r.add("bingham", make_viscous_fluid<D>);
}

template class MaterialRegistry<2>;
template class MaterialRegistry<3>;
template void register_materials<2>(MaterialRegistry<2>&);
template void register_materials<3>(MaterialRegistry<3>&);

}  // namespace dmi
