// Binary state archive for checkpoints (engine/sim/checkpoint.hpp): the dynamic state of a run in the exact bits
// the solver holds, so a restarted run continues bit for bit. Sections are tagged so a reader that drifts out of
// step with the writer fails with the tag it expected instead of reading garbage. Native byte order: a checkpoint
// is read back on the machine kind that wrote it (it is not an archive format; results.h5 is).
#pragma once
#include <Eigen/Dense>
#include <cstdint>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "engine/common/error.hpp"

namespace dmi {

// Values stored by their bytes: trivially copyable types and fixed-size Eigen matrices (plain arrays of scalars).
template <class T, class = void> struct is_fixed_eigen : std::false_type {};
template <class T>
struct is_fixed_eigen<T, std::void_t<typename T::Scalar, decltype(T::RowsAtCompileTime)>>
    : std::bool_constant<(T::RowsAtCompileTime > 0 && T::ColsAtCompileTime > 0 &&
                          sizeof(T) == sizeof(typename T::Scalar) * T::RowsAtCompileTime * T::ColsAtCompileTime)> {};
template <class T> inline constexpr bool is_state_pod_v = std::is_trivially_copyable_v<T> || is_fixed_eigen<T>::value;

class StateWriter {
 public:
  template <class T> void put(const T& v) {
    static_assert(is_state_pod_v<T>, "put: trivially copyable values only");
    const auto* p = reinterpret_cast<const char*>(&v);
    buf_.append(p, sizeof(T));
  }
  template <class T> void put(const std::vector<T>& v) {
    static_assert(is_state_pod_v<T>, "put: vectors of trivially copyable values only");
    put<std::uint64_t>(v.size());
    buf_.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
  void put(const std::vector<bool>&) = delete;
  void put(const std::string& s) {
    put<std::uint64_t>(s.size());
    buf_.append(s);
  }
  void put(const Eigen::VectorXd& v) {
    put<std::uint64_t>(static_cast<std::uint64_t>(v.size()));
    buf_.append(reinterpret_cast<const char*>(v.data()), static_cast<std::size_t>(v.size()) * sizeof(double));
  }
  void tag(const char* name) { put(std::string(name)); }
  const std::string& bytes() const { return buf_; }

 private:
  std::string buf_;
};

class StateReader {
 public:
  StateReader(std::string bytes, std::string file) : buf_(std::move(bytes)), file_(std::move(file)) {}
  template <class T> void get(T& v) {
    static_assert(is_state_pod_v<T>, "get: trivially copyable values only");
    std::memcpy(static_cast<void*>(&v), take(sizeof(T)), sizeof(T));
  }
  template <class T> T get() {
    T v;
    get(v);
    return v;
  }
  template <class T> void get(std::vector<T>& v) {
    static_assert(is_state_pod_v<T>, "get: vectors of trivially copyable values only");
    const auto n = count(sizeof(T));
    v.resize(n);
    if (n) std::memcpy(static_cast<void*>(v.data()), take(n * sizeof(T)), n * sizeof(T));
  }
  void get(std::string& s) {
    const auto n = count(1);
    s.assign(take(n), n);
  }
  void get(Eigen::VectorXd& v) {
    const auto n = count(sizeof(double));
    v.resize(static_cast<Eigen::Index>(n));
    if (n) std::memcpy(v.data(), take(n * sizeof(double)), n * sizeof(double));
  }
  // Reads a tag and fails unless it is `name`.
  void tag(const char* name) {
    std::string t;
    get(t);
    if (t != name) fail("section '" + std::string(name) + "' expected, found '" + t.substr(0, 40) + "'");
  }
  // A restored array must match what the scenario rebuilt (same particle count, DOFs, series).
  void expect_size(const char* what, std::size_t got, std::size_t want) const {
    if (got != want)
      fail(std::string(what) + " has " + std::to_string(got) + " entries, the scenario gives " + std::to_string(want) +
           " (a checkpoint of another scenario or version)");
  }
  bool at_end() const { return pos_ == buf_.size(); }
  [[noreturn]] void fail(const std::string& what) const { throw InputError(file_ + ": checkpoint: " + what); }

 private:
  std::size_t count(std::size_t elem) {
    const auto n = get<std::uint64_t>();
    if (n > (buf_.size() - pos_) / elem) fail("truncated (an array of " + std::to_string(n) + " entries runs past the end)");
    return static_cast<std::size_t>(n);
  }
  const char* take(std::size_t n) {
    if (n > buf_.size() - pos_) fail("truncated at byte " + std::to_string(pos_));
    const char* p = buf_.data() + pos_;
    pos_ += n;
    return p;
  }
  std::string buf_, file_;
  std::size_t pos_ = 0;
};

}  // namespace dmi
