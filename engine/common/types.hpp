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
// region, more than a small loop's work.
constexpr Index kParallelMin = 4096;

// A run with fewer particles than this steps on one thread whatever -t says: its loops above kParallelMin (grid nodes,
// mid-sized bodies) and the step's many short parallel regions cost more in wake-ups than they share. Measured
// (2 threads against 1, passive wait policy): the 2D kernel 0.66x at 10 k particles, 1.14x at 30 k; the water dam
// break 0.94x at 8 k, 1.26x at 33 k, 1.4x at 100 k; the buffered dam at 19.6 k 0.85x, the 3D slit dam at 17.6 k 0.92x.
constexpr Index kParallelScene = 25000;

// Symmetric stress in Voigt order (xx, yy, zz, xy, yz, xz). In 2D the last two are zero.
using Voigt6 = Eigen::Matrix<double, 6, 1>;

}  // namespace dmi
