// Structural damping of a frame besides Rayleigh's C = alpha M + beta K (FrameModel::rayleigh_*).
#pragma once
#include <limits>

namespace dmi {

// Modal damping: every mode of (K0, M) with frequency up to max_frequency damped at one ratio,
//   C_modal = sum_i 2 zeta omega_i (M phi_i)(M phi_i)^T,  phi_i^T M phi_j = delta_ij
// (superposition of modal damping matrices: Clough & Penzien 1993, sec. 12-6; Chopra 2012, sec. 11.4), so each
// mode keeps zeta whatever its frequency, unlike Rayleigh damping, whose ratio grows with frequency above its
// fitting band. The modes are computed from the assembled frame (AssembledSystem: dense, at most kModalDenseMax
// free DOFs); modes above max_frequency are left undamped.
struct ModalDamping {
  double ratio = 0.0;                                              // zeta; 0 = none
  double max_frequency = std::numeric_limits<double>::infinity();  // Hz
};

}  // namespace dmi
