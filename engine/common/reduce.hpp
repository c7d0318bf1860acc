// Deterministic parallel sum: fixed chunks summed in parallel, partials added in chunk order,
// so the result is bit-identical for any thread count (engine/common/parallel.hpp, parallel_reduce).
#pragma once
#include <functional>

#include "engine/common/parallel.hpp"
#include "engine/common/types.hpp"

namespace dmi {

template <class F> double deterministic_sum(Index n, F&& term) { return parallel_reduce(Index(0), n, 0.0, term, std::plus<double>()); }

}  // namespace dmi
