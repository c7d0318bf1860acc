// Reading the JSON files a user hands us (scenarios, sweeps, limits) within bounds: a size limit (reading /dev/zero or a
// mistaken multi-gigabyte file fails at once instead of filling memory), and a nesting-depth limit checked before the
// recursive parser sees the text (100 000 nested brackets overflowed the stack). No input of this tool nests deeper
// than a handful of levels.
#pragma once
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <string>

#include "engine/common/error.hpp"

namespace dmi {

constexpr std::size_t kMaxJsonBytes = std::size_t{64} << 20;  // 64 MiB
constexpr int kMaxJsonDepth = 64;

// The text of a JSON input file; `what` names it in messages ("scenario", "limits", ...).
inline std::string read_json_file(const std::string& path, const std::string& what) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(path + ": is a directory, not a " + what + " file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": cannot open the " + what + " file (does it exist and is it readable?)");
  std::string text;
  char buf[1 << 16];
  while (in.read(buf, sizeof buf) || in.gcount() > 0) {
    text.append(buf, static_cast<std::size_t>(in.gcount()));
    if (text.size() > kMaxJsonBytes)
      throw InputError(path + ": larger than " + std::to_string(kMaxJsonBytes >> 20) + " MiB: expected a " + what + " file (JSON text)");
  }
  return text;
}

// Refuses text nested deeper than kMaxJsonDepth arrays/objects (brackets inside strings do not count).
inline void check_json_depth(const std::string& text, const std::string& file) {
  int depth = 0;
  bool in_string = false, escaped = false;
  std::size_t line = 1, col = 0;
  for (const char c : text) {
    ++col;
    if (c == '\n') ++line, col = 0;
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false;
      continue;
    }
    if (c == '"') in_string = true;
    else if (c == '[' || c == '{') {
      if (++depth > kMaxJsonDepth)
        throw InputError(file + ":" + std::to_string(line) + ":" + std::to_string(col) + ": invalid JSON (nested deeper than " +
                         std::to_string(kMaxJsonDepth) + " levels)");
    } else if (c == ']' || c == '}') {
      --depth;
    }
  }
}

}  // namespace dmi
