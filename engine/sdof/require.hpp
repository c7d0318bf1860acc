// Argument checks of the closed-form tools: std::invalid_argument naming the function, argument, value and the
// expected range.
#pragma once
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace dmi::sdof::detail {

[[noreturn]] inline void fail(const char* function, const char* argument, double value, const char* expected) {
  std::ostringstream s;
  s.precision(17);
  s << "dmi::sdof::" << function << ": " << argument << " = " << value << ", expected " << expected;
  throw std::invalid_argument(s.str());
}

inline void require_positive(const char* function, const char* argument, double value) {
  if (!(std::isfinite(value) && value > 0)) fail(function, argument, value, "a finite value > 0");
}

inline void require_non_negative(const char* function, const char* argument, double value) {
  if (!(std::isfinite(value) && value >= 0)) fail(function, argument, value, "a finite value >= 0");
}

inline void require_finite(const char* function, const char* argument, double value) {
  if (!std::isfinite(value)) fail(function, argument, value, "a finite value");
}

inline void require_poisson(const char* function, const char* argument, double value) {
  if (!(std::isfinite(value) && value > -1 && value < 0.5)) fail(function, argument, value, "-1 < nu < 0.5");
}

}  // namespace dmi::sdof::detail
