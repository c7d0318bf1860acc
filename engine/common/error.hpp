// Errors that cross layer boundaries. The CLI maps both to exit code 2.
#pragma once
#include <stdexcept>
#include <string>

namespace dmi {

// Bad input: names the file, the JSON path, the offending value and what was expected.
class InputError : public std::runtime_error {
 public:
  InputError(const std::string& file, const std::string& path, const std::string& value,
             const std::string& expected)
      : std::runtime_error(format(file, path, value, expected)) {}
  explicit InputError(const std::string& message) : std::runtime_error(message) {}

 private:
  static std::string format(const std::string& file, const std::string& path,
                            const std::string& value, const std::string& expected) {
    std::string s = file.empty() ? std::string("<scenario>") : file;
    s += ": " + (path.empty() ? std::string("/") : path);
    if (!value.empty()) s += " = " + value;
    s += ": expected " + expected;
    return s;
  }
};

// A run that cannot go on (NaN, particle outside the grid, ...): names step, time, body, particle.
class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The run was stopped by SIGINT or SIGTERM; the CLI exits with 128 + signal.
class Interrupted : public std::runtime_error {
 public:
  Interrupted(int signal, const std::string& message) : std::runtime_error(message), signal_(signal) {}
  int signal() const { return signal_; }

 private:
  int signal_;
};

}  // namespace dmi
