// Builds history series (energies, momentum, wall/region forces, probes) and particle snapshots
// from a solver, without the solver knowing about output.
#pragma once
#include <string>
#include <vector>

#include "engine/io/results.hpp"
#include "engine/mpm/solver.hpp"

namespace dmi {

template <int D> class Recorder {
 public:
  Recorder(const Solver<D>& solver, const Scenario& s);
  void sample(const Solver<D>& solver, double dt);  // appends one row to every series
  Snapshot snapshot(const Solver<D>& solver) const;
  const std::vector<double>& time() const { return time_; }
  std::vector<Series>& series() { return series_; }
  double initial_energy() const { return e0_; }

 private:
  struct Probe {
    std::string name;
    bool particle = false;
    Index index = 0;      // tracked particle
    int body = 0;
    std::vector<std::string> quantities;
  };
  Series& add(const std::string& path, const std::string& unit, std::vector<std::string> comps);
  std::vector<double> time_;
  std::vector<Series> series_;
  std::vector<Probe> probes_;
  double e0_ = 0;
};

}  // namespace dmi
