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

// Loops shorter than this run on one thread: waking OpenMP threads costs ~10-50 us per parallel
// region, more than a small loop's work (a 200-particle run was 10x slower in parallel).
constexpr Index kParallelMin = 4096;

// Symmetric stress in Voigt order (xx, yy, zz, xy, yz, xz). In 2D the last two are zero.
using Voigt6 = Eigen::Matrix<double, 6, 1>;

}  // namespace dmi
