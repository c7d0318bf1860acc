// Coulomb's friction law as one projection, shared by every contact (walls, bodies, members, rigid bodies): the
// tangential part t of a contact force, impulse or velocity correction is kept whole while |t| <= limit = mu N (stick)
// and scaled down to the limit along its own direction when it exceeds it (slip) (Bardenhagen, Brackbill & Sulsky 2000,
// eq. 14; Lin & Yang 2024, eq. (21)). A caller passes the tangential part it would apply to stop the slip and the
// friction limit for the normal part it applies.
#pragma once
#include <cmath>

namespace dmi {

template <class V> V coulomb_projection(const V& t, double limit) {
  const double n = t.norm();
  if (n <= limit) return t;
  return V(t * (limit / n));
}

}  // namespace dmi
