// Basic aliases shared by every layer. Units are SI throughout (m, kg, s, N, Pa).
#pragma once
#include <Eigen/Dense>
#include <cstddef>
#include <cstdint>

namespace dmi {

template <int D> using Vec = Eigen::Matrix<double, D, 1>;
template <int D> using Mat = Eigen::Matrix<double, D, D>;
template <int D> using IVec = Eigen::Matrix<int, D, 1>;
using Index = std::int64_t;

// Symmetric stress in Voigt order (xx, yy, zz, xy, yz, xz). In 2D the last two are zero.
using Voigt6 = Eigen::Matrix<double, 6, 1>;

}  // namespace dmi
