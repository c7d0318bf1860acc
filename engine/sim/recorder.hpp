// Builds history series (energies, momentum, wall/region forces, probes) and particle snapshots
// from a solver, without the solver knowing about output.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "engine/io/results.hpp"
#include "engine/io/vtu.hpp"
#include "engine/mpm/solver.hpp"
#include "engine/scenario/config.hpp"
#include "engine/sim/pressure_recorder.hpp"

namespace dmi {

template <int D> class Recorder {
 public:
  Recorder(const Solver<D>& solver, const Scenario& s);
  // Adds the boundary forces of the step just taken (length dt) to the interval impulse.
  void accumulate(const Solver<D>& solver, double dt);
  // Appends one row to every series. Wall and region forces are the mean over the steps since the
  // last sample (impulse / elapsed time), so a sparse history keeps the impulse; every-step
  // histories hold each step's force.
  void sample(const Solver<D>& solver, double dt);
  Snapshot snapshot(const Solver<D>& solver) const;
  // Members sampled along their deformed centre-lines (9 points per element) with section forces and
  // fibre stresses, for ParaView.
  static LineSnapshot member_snapshot(const FrameOf<D>& f);
  const std::vector<double>& time() const { return time_; }
  std::vector<Series>& series() { return series_; }
  double initial_energy() const { return e0_; }
  // The members' contact loads at the step with the largest total contact force (core/peak_contact.hpp); none if
  // the members were never touched.
  std::optional<PeakContact> peak_contact(const FrameOf<D>& f) const;
  // The face profile's record (engine/sim/pressure_recorder.hpp); none if the scenario has none.
  std::optional<FaceProfileRecord> face_profile() const { return pressures_.face_profile(); }
  // Histories so far and the interval accumulators, for checkpoints (the series layout comes from the scenario).
  void save_state(StateWriter& w) const;
  void load_state(StateReader& r);

 private:
  struct Probe {
    std::string name;
    bool particle = false;
    bool member = false;
    int element = 0;      // member probes: element and local coordinate
    double xi = 0;
    Index index = 0;      // tracked particle
    int body = 0;
    std::vector<std::string> quantities;
  };
  Series& add(const std::string& path, const std::string& unit, std::vector<std::string> comps);
  void add_frame_series(const FrameOf<D>& f, const Scenario& s);
  void sample_frame(const FrameOf<D>& f, const MemberContact<D>& mc, const Diagnostics<D>& d, std::size_t& k);
  void sample_member_probe(const Frame& f, const Probe& p, const std::string& q, Series& s) const;
  std::vector<double> time_;
  std::vector<Series> series_;
  std::vector<Probe> probes_;
  std::vector<Vec<D>> impulse_;  // per wall, region and inflow zone, since the last sample (N s)
  Vec<D> member_impulse_ = Vec<D>::Zero();  // of the material on the members since the last sample (N s)
  double elapsed_ = 0;           // s since the last sample
  double peak_contact_ = 0, peak_contact_time_ = 0;  // largest |total contact force| (N) and when
  std::vector<ContactLoadOf<D>> peak_loads_;
  double e0_ = 0;
  PressureRecorder<D> pressures_;
};

}  // namespace dmi
