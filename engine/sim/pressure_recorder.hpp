// Pressure histories for results.h5: sensors on walls and member faces (engine/mpm/sensor.hpp), and the pressure
// profile along a struck face made of members (the normal contact force on each element per unit face area, its
// resultant and the resultant's position along the face). Interval means, like the wall forces: the impulse over the
// steps since the last sample, divided by the elapsed time.
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "engine/common/state_io.hpp"
#include "engine/io/results.hpp"
#include "engine/mpm/solver.hpp"
#include "engine/scenario/config.hpp"

namespace dmi {

template <int D> class PressureRecorder {
 public:
  PressureRecorder(const Solver<D>& solver, const Scenario& s);
  // Appends the series this recorder fills (sensors/<name>/pressure, face/pressure, face/resultant, face/height).
  void add_series(std::vector<Series>& out) const;
  void accumulate(const Solver<D>& solver, double dt);
  // Writes one row to the series add_series appended, starting at out[k]; advances k; clears the interval.
  void sample(std::vector<Series>& out, std::size_t& k, double elapsed);
  // The face's members, load direction, width and each bin's span along the face (core/face_profile.hpp); none if the
  // scenario has no face profile.
  std::optional<FaceProfileRecord> face_profile() const;
  void save_state(StateWriter& w) const;
  void load_state(StateReader& r);

 private:
  struct WallSensor { std::size_t wall = 0, index = 0; };
  struct MemberSensor { PressurePatch<D> patch; int first = 0, last = 0; };  // elements [first, last)
  // An element of the face: its span along the face (m), and the height of its ends above the face's foot, measured
  // across the load direction (the lever arm of a load there about the foot).
  struct Bin { std::string member; int element = 0; double from = 0, to = 0, height_from = 0, height_to = 0; };
  double h_ = 0;
  std::vector<WallSensor> walls_;
  std::vector<std::string> wall_names_;
  std::vector<double> wall_area_;
  std::vector<MemberSensor> members_;
  std::vector<Bin> bins_;
  std::vector<int> bin_of_;        // per element: its bin, -1 when not on the face
  std::vector<std::string> face_members_;
  Vec<D> direction_ = Vec<D>::Zero();
  Vec<D> foot_ = Vec<D>::Zero();   // the face's first node (initial position)
  double arm(const Vec<D>& x) const {  // height of x above the foot across the load direction
    const Vec<D> r = x - foot_;
    return (r - r.dot(direction_) * direction_).norm();
  }
  double width_ = 0;
  std::vector<double> impulse_;    // wall sensors, member sensors, face bins (N s)
  double moment_ = 0;              // sum of the face's normal impulse times its arm about the foot (N s m)
};

}  // namespace dmi
