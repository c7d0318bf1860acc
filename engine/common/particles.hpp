// Particle storage, struct-of-arrays: one contiguous array per field, indexed by particle.
// Bodies own contiguous index ranges [begin, end), so material laws run once per range.
// In 2D, mass and volume include the out-of-plane thickness: forces are in N, energies in J.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "engine/common/parallel.hpp"
#include "engine/common/state_io.hpp"
#include "engine/common/types.hpp"

namespace dmi {

template <int D> struct Particles {
  std::vector<Vec<D>> x;          // position (m)
  std::vector<Vec<D>> x0;         // initial position (m): displacement = x - x0
  std::vector<Vec<D>> v;          // velocity (m/s)
  std::vector<Vec<D>> half_size;  // GIMP half-length of the particle domain (m)
  // Reach of the body from the particle centre along -e_d and +e_d, undeformed (m): half_size inside the body, the
  // distance to the seeded shape's surface for particles next to it (surface contact detection, touch.hpp).
  std::vector<Vec<D>> reach_lo, reach_hi;
  std::vector<Mat<D>> F;          // in-plane deformation gradient
  std::vector<Mat<D>> L;          // velocity gradient of the last step (1/s)
  std::vector<Mat<D>> C;          // APIC affine velocity matrix (1/s)
  std::vector<Mat<D>> stress;     // Cauchy stress, in-plane part (Pa), tension positive
  std::vector<double> stress_zz;  // out-of-plane normal stress in 2D (Pa); unused in 3D
  std::vector<double> mass;       // kg
  std::vector<double> vol0, vol;  // initial and current volume (m^3)
  std::vector<int> body;          // body index
  // The solver reorders particles by tile every few steps (locality): id[i] is particle i's index at creation,
  // slot[k] the current index of the particle created k-th. Outputs and probes use creation order.
  std::vector<Index> id, slot;

  std::size_t size() const { return x.size(); }
  // Bytes of one particle over all the arrays above (x, x0, v, half_size, reach_lo, reach_hi; F, L, C, stress; stress_zz, mass, vol0,
  // vol; body; id, slot).
  static constexpr std::size_t kBytesPerParticle = 6 * sizeof(Vec<D>) + 4 * sizeof(Mat<D>) + 4 * sizeof(double) + sizeof(int) + 2 * sizeof(Index);

 private:
  std::vector<double> scratch_;  // permute's gather buffer, kept between reorderings

 public:

  // new[i] = old[perm[i]] for every field; perm keeps each body inside its index range. Each field is gathered into
  // one reused scratch buffer and copied back: a fresh array per field (32 MB for 1 M particles' matrices, above
  // malloc's mmap threshold) would be mapped and faulted in page by page at every reordering.
  void permute(const std::vector<Index>& perm) {
    const Index n = static_cast<Index>(perm.size());
    auto apply = [&](auto& v) {
      using T = typename std::remove_reference_t<decltype(v)>::value_type;
      static_assert(std::is_standard_layout_v<T>);  // plain values (fixed-size Eigen: an array of doubles), bytewise copyable
      scratch_.resize(std::max(scratch_.size(), (perm.size() * sizeof(T) + sizeof(double) - 1) / sizeof(double)));
      T* o = reinterpret_cast<T*>(scratch_.data());
      T* d = v.data();
      parallel_for(0, n, [&](Index i) { std::memcpy(static_cast<void*>(o + i), d + perm[i], sizeof(T)); });
      parallel_for(0, n, [&](Index i) { std::memcpy(static_cast<void*>(d + i), o + i, sizeof(T)); });
    };
    apply(x), apply(x0), apply(v), apply(half_size), apply(reach_lo), apply(reach_hi), apply(F), apply(L), apply(C), apply(stress), apply(stress_zz);
    apply(mass), apply(vol0), apply(vol), apply(body), apply(id);
    for (std::size_t i = 0; i < id.size(); ++i) slot[id[i]] = static_cast<Index>(i);
  }

  // Every field, for checkpoints. The count is the saved one (an inflow adds particles as the run goes).
  void save_state(StateWriter& w) const {
    w.tag("particles");
    w.put(x), w.put(x0), w.put(v), w.put(half_size), w.put(reach_lo), w.put(reach_hi), w.put(F), w.put(L), w.put(C), w.put(stress), w.put(stress_zz);
    w.put(mass), w.put(vol0), w.put(vol), w.put(body), w.put(id), w.put(slot);
  }
  void load_state(StateReader& r) {
    r.tag("particles");
    r.get(x);
    const std::size_t n = size();
    r.get(x0), r.get(v), r.get(half_size), r.get(reach_lo), r.get(reach_hi), r.get(F), r.get(L), r.get(C), r.get(stress), r.get(stress_zz);
    r.get(mass), r.get(vol0), r.get(vol), r.get(body), r.get(id), r.get(slot);
    for (std::size_t k : {x0.size(), v.size(), half_size.size(), reach_lo.size(), reach_hi.size(), F.size(), L.size(), C.size(), stress.size(),
                          stress_zz.size(), mass.size(), vol0.size(), vol.size(), body.size(), id.size(), slot.size()})
      r.expect_size("a particle array", k, n);
    r.expect_size("particles", x.size(), n);
  }

  // Appends one particle at rest state; fields that a material must set start as NaN-free zeros.
  void push(const Vec<D>& pos, const Vec<D>& vel, const Vec<D>& half, double m, double volume, int b) { push(pos, vel, half, m, volume, b, half, half); }
  void push(const Vec<D>& pos, const Vec<D>& vel, const Vec<D>& half, double m, double volume, int b, const Vec<D>& lo, const Vec<D>& hi) {
    x.push_back(pos);
    x0.push_back(pos);
    v.push_back(vel);
    half_size.push_back(half);
    reach_lo.push_back(lo);
    reach_hi.push_back(hi);
    F.push_back(Mat<D>::Identity());
    L.push_back(Mat<D>::Zero());
    C.push_back(Mat<D>::Zero());
    stress.push_back(Mat<D>::Zero());
    stress_zz.push_back(0.0);
    mass.push_back(m);
    vol0.push_back(volume);
    vol.push_back(volume);
    body.push_back(b);
    id.push_back(static_cast<Index>(slot.size()));
    slot.push_back(static_cast<Index>(slot.size()));
  }
};

// Full symmetric stress of particle p in Voigt order (xx, yy, zz, xy, yz, xz).
template <int D> Voigt6 voigt_stress(const Particles<D>& p, std::size_t i) {
  Voigt6 s = Voigt6::Zero();
  const Mat<D>& t = p.stress[i];
  if constexpr (D == 2) {
    s << t(0, 0), t(1, 1), p.stress_zz[i], t(0, 1), 0.0, 0.0;
  } else {
    s << t(0, 0), t(1, 1), t(2, 2), t(0, 1), t(1, 2), t(0, 2);
  }
  return s;
}

// von Mises equivalent stress of a Voigt stress.
inline double von_mises(const Voigt6& s) {
  const double a = s[0] - s[1], b = s[1] - s[2], c = s[2] - s[0];
  return std::sqrt(0.5 * (a * a + b * b + c * c) + 3.0 * (s[3] * s[3] + s[4] * s[4] + s[5] * s[5]));
}

}  // namespace dmi
