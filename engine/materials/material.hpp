// Material interface: one call per body (a contiguous particle range), never per particle
// inside the transfer kernels. Laws read the velocity gradient L and deformation gradient F
// (already advanced by the solver) and write stress, out-of-plane stress and current volume.
// History-dependent laws (viscoelastic rubber, Drucker-Prager, Bingham) keep their internal
// variables in arrays of their own, sized in attach() and indexed by particle index.
// Fluids (newtonian, bingham) keep only J = det F and reset F to J^(1/D) I in update().
#pragma once
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "engine/common/state_io.hpp"
#include "engine/common/particles.hpp"
#include "core/options.hpp"

namespace dmi {

template <int D> class Material {
 public:
  virtual ~Material() = default;
  virtual double density() const = 0;      // kg/m^3
  virtual double wave_speed() const = 0;   // fastest elastic wave speed (m/s), for the CFL step
  // Called once per body using this material, before the first step: size internal variables.
  virtual void attach(const Particles<D>& /*p*/, Index /*begin*/, Index /*end*/) {}
  // Stress update over particles [begin, end) for a step of length dt (s).
  virtual void update(Particles<D>& p, Index begin, Index end, double dt) = 0;
  // True when update() is pointwise: each particle's new state depends on that particle alone and nothing is
  // accumulated across particles, so disjoint sub-ranges may be updated concurrently and in any split with the
  // same result. The solver then updates stresses chunk by chunk inside G2P, while L and F are still in cache.
  virtual bool pointwise() const { return false; }
  // For a fluid whose only state is its volume ratio J (F = J^(1/D) I): the time, in acoustic transits of a cell, over
  // which J relaxes towards the space its particles fill (engine/mpm/fluid_volume.hpp); 0: not relaxed.
  virtual double volume_relaxation() const { return 0.0; }
  // Stored (recoverable) strain energy of particles [begin, end) (J).
  virtual double strain_energy(const Particles<D>& p, Index begin, Index end) const = 0;
  // Energy dissipated since t = 0 (viscosity, plasticity) by all bodies of this material (J).
  virtual double dissipated() const { return 0.0; }
  // Stiffness-proportional viscous time beta (s): the stress has a part beta C:D. It lowers the
  // explicit stable step to (2/omega)(sqrt(1 + zeta^2) - zeta), zeta = beta omega / 2.
  virtual double damping_time() const { return 0.0; }
  // Kelvin-Voigt laws whose viscous stress sigma_v = a tr(D) I + 2 b D has constant coefficients (Pa s) return
  // {a, b} and keep the last update's sigma_v per particle (viscous_stress(), indexed like the particles); the
  // solver then integrates that part implicitly on the grid (engine/mpm/viscous.hpp) and its step is the elastic
  // one. Others return false and their damping_time() cuts the explicit step.
  virtual bool viscous_coefficients(double& /*a*/, double& /*b*/) const { return false; }
  virtual const std::vector<Mat<D>>* viscous_stress() const { return nullptr; }
  // While on, update() still keeps the viscous stress but leaves its dissipation to the implicit solve, which counts
  // the work of the viscous nodal forces on the grid's final velocities.
  virtual void set_implicit_viscosity(bool /*on*/) {}
  // Makes particles [begin, end) stress-free in their present configuration (a body turning rigid, Solver::
  // switch_free_bodies); false where the law cannot (its stress follows from F or from a history it cannot drop).
  virtual bool relax(Particles<D>& /*p*/, Index /*begin*/, Index /*end*/) { return false; }
  // Starts particle i from the full (3x3) Cauchy stress sigma (a geostatic state), before attach(): false where the
  // law cannot (its stress follows from F). A fluid takes the pressure -tr(sigma)/3 and the volume ratio J it implies.
  virtual bool prestress(Particles<D>& /*p*/, Index /*i*/, const Mat<3>& /*sigma*/) { return false; }
  // The solver reordered the particles: new[i] = old[perm[i]]; laws with per-particle arrays follow.
  virtual void permute(const std::vector<Index>& /*perm*/) {}
  // Internal variables (per-particle arrays, dissipated energy) for checkpoints; laws without any write nothing.
  virtual void save_state(StateWriter& /*w*/) const {}
  virtual void load_state(StateReader& /*r*/) {}
};

// Reorders a per-particle array (new[i] = old[perm[i]]); arrays of another size are left alone.
template <class T> void permute_array(std::vector<T>& v, const std::vector<Index>& perm) {
  if (v.size() != perm.size()) return;
  std::vector<T> o(v.size());
  for (std::size_t i = 0; i < perm.size(); ++i) o[i] = v[perm[i]];
  v.swap(o);
}

// Lamé constants from E and nu (3D / plane strain).
struct Elastic {
  double E, nu, lambda, mu;
  Elastic(double E_, double nu_) : E(E_), nu(nu_), lambda(E_ * nu_ / ((1 + nu_) * (1 - 2 * nu_))), mu(E_ / (2 * (1 + nu_))) {}
  // Complementary strain energy density of a stress (J/m^3): [(1 + nu) sigma:sigma - nu (tr sigma)^2] / (2E).
  double energy_density(const Voigt6& s) const {
    const double ss = s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + 2 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]);
    const double tr = s[0] + s[1] + s[2];
    return ((1 + nu) * ss - nu * tr * tr) / (2 * E);
  }
  // P-wave speed: sqrt(E/(rho(1-nu^2))) in plane stress, sqrt((lambda+2mu)/rho) otherwise.
  double wave_speed(double rho, Plane plane) const {
    const double M = plane == Plane::stress ? E / (1 - nu * nu) : lambda + 2 * mu;
    return std::sqrt(M / rho);
  }
};

// Explicit registry of material laws: name -> factory. Filled by register_materials(); no static
// initialiser tricks, so a static library cannot silently drop a law.
template <int D> class MaterialRegistry {
 public:
  using Factory = std::function<std::unique_ptr<Material<D>>(const MaterialConfig&, Plane)>;
  void add(const std::string& model, Factory f) { factories_[model] = std::move(f); }
  std::unique_ptr<Material<D>> make(const MaterialConfig& c, Plane plane) const;
  bool has(const std::string& model) const { return factories_.count(model) != 0; }

 private:
  std::map<std::string, Factory> factories_;
};

template <int D> void register_materials(MaterialRegistry<D>& r);

}  // namespace dmi
