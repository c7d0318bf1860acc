#include "design/dynamic_strength.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace dmi::design {

namespace {
void require_rate(double r, const char* who) {
  if (!std::isfinite(r) || r < 0) throw std::invalid_argument(std::string(who) + ": strain rate must be finite and >= 0");
}
void require_positive(double v, const char* what) {
  if (!std::isfinite(v) || v <= 0) throw std::invalid_argument(std::string("strain rate estimate: ") + what + " must be finite and > 0");
}
}  // namespace

double dif_compression(double strain_rate) {
  require_rate(strain_rate, "dif_compression");
  if (strain_rate <= kMc2010CompressionReferenceRate) return 1.0;
  const double ratio = strain_rate / kMc2010CompressionReferenceRate;
  return strain_rate <= kMc2010CompressionBranchRate ? std::pow(ratio, 0.014) : 0.012 * std::cbrt(ratio);
}

double dif_tension(double strain_rate) {
  require_rate(strain_rate, "dif_tension");
  if (strain_rate <= kMc2010TensionReferenceRate) return 1.0;
  const double ratio = strain_rate / kMc2010TensionReferenceRate;
  return strain_rate <= kMc2010TensionBranchRate ? std::pow(ratio, 0.018) : 0.0062 * std::cbrt(ratio);
}

double strain_rate_from_stress_rate(double stress_rate_Pa_per_s, double E_Pa) {
  if (!std::isfinite(stress_rate_Pa_per_s)) throw std::invalid_argument("strain rate estimate: stress rate must be finite");
  require_positive(E_Pa, "E");
  return std::abs(stress_rate_Pa_per_s) / E_Pa;
}

double strain_rate_from_rise_time(double peak_stress_Pa, double E_Pa, double rise_time_s) {
  if (!std::isfinite(peak_stress_Pa)) throw std::invalid_argument("strain rate estimate: peak stress must be finite");
  require_positive(E_Pa, "E");
  require_positive(rise_time_s, "rise time");
  return std::abs(peak_stress_Pa) / (E_Pa * rise_time_s);
}

}  // namespace dmi::design
