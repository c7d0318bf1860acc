// Internal to dmi_io (not installed, not included outside engine/io): small RAII and error
// helpers over the HDF5 C API shared by results_writer.cpp and results_reader.cpp.
// Every failure becomes std::runtime_error("<file>: <what failed> (HDF5: <innermost reason>)").
#pragma once
#include <hdf5.h>

#include <stdexcept>
#include <string>
#include <utility>

namespace dmi::h5 {

// Owns one HDF5 identifier and closes it with the matching H5?close function.
class Handle {
 public:
  using Closer = herr_t (*)(hid_t);
  Handle() = default;
  Handle(hid_t id, Closer closer) : id_(id), close_(closer) {}
  ~Handle() { close(); }
  Handle(Handle&& o) noexcept : id_(std::exchange(o.id_, -1)), close_(o.close_) {}
  Handle& operator=(Handle&& o) noexcept {
    if (this != &o) {
      close();
      id_ = std::exchange(o.id_, -1);
      close_ = o.close_;
    }
    return *this;
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;

  hid_t get() const { return id_; }
  operator hid_t() const { return id_; }  // NOLINT: pass straight to H5 calls
  bool valid() const { return id_ >= 0; }
  herr_t close() {
    herr_t r = 0;
    if (id_ >= 0 && close_ != nullptr) r = close_(id_);
    id_ = -1;
    return r;
  }

 private:
  hid_t id_ = -1;
  Closer close_ = nullptr;
};

// Turns off HDF5's automatic printing of error stacks to stderr (we report through exceptions).
inline void silence_errors() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

// The innermost (most specific) description on the current HDF5 error stack; clears the stack.
inline std::string last_error() {
  std::string desc;
  auto walk = [](unsigned n, const H5E_error2_t* e, void* data) -> herr_t {
    if (n == 0 && e != nullptr && e->desc != nullptr) *static_cast<std::string*>(data) = e->desc;
    return 0;
  };
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, walk, &desc);
  H5Eclear2(H5E_DEFAULT);
  return desc;
}

[[noreturn]] inline void fail(const std::string& file, const std::string& what) {
  std::string msg = file + ": " + what;
  const std::string detail = last_error();
  if (!detail.empty()) msg += " (HDF5: " + detail + ")";
  throw std::runtime_error(msg);
}

// Throws unless id is a valid identifier; returns it so calls can be wrapped inline.
inline hid_t check_id(hid_t id, const std::string& file, const std::string& what) {
  if (id < 0) fail(file, what);
  return id;
}
inline void check_ok(herr_t status, const std::string& file, const std::string& what) {
  if (status < 0) fail(file, what);
}

// Fixed-length UTF-8 string type of `size` bytes, NUL-padded: how every string in results.h5 is
// written. (Fixed rather than variable length keeps string data inline, out of HDF5's global
// heap, whose corruption can make the HDF5 1.10 library loop forever while reading.)
inline Handle fixed_string_type(std::size_t size, const std::string& file) {
  Handle t(check_id(H5Tcopy(H5T_C_S1), file, "cannot create string type"), H5Tclose);
  check_ok(H5Tset_size(t, size), file, "cannot create string type");
  check_ok(H5Tset_strpad(t, H5T_STR_NULLPAD), file, "cannot create string type");
  check_ok(H5Tset_cset(t, H5T_CSET_UTF8), file, "cannot create string type");
  return t;
}

}  // namespace dmi::h5
