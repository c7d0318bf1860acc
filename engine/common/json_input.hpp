// Reading the JSON files a user hands us (scenarios, sweeps, limits) within bounds: a size limit (reading /dev/zero or a
// mistaken multi-gigabyte file fails at once instead of filling memory), and a nesting-depth limit checked before the
// recursive parser sees the text (100 000 nested brackets overflowed the stack). No input of this tool nests deeper
// than a handful of levels. Repeated keys are refused there too.
#pragma once
#include <cstddef>
#include <filesystem>
#include <fstream>
#include <algorithm>
#include <string>
#include <vector>

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

// Structural checks the recursive parser cannot make safely or at all, on the raw text before it parses it: nesting
// deeper than kMaxJsonDepth arrays/objects, and a key repeated in one object (JSON keeps the last one silently, so
// the first value the user wrote would be ignored). Keys compare as written (escapes not decoded).
inline void check_json_structure(const std::string& text, const std::string& file) {
  struct Frame {
    bool object;
    std::vector<std::string> keys;
    std::string key;  // the current key (objects)
    long index = 0;   // the current element (arrays)
    bool want_key = true;
  };
  std::vector<Frame> stack;
  std::size_t line = 1, col = 0;
  auto where = [&] { return file + ":" + std::to_string(line) + ":" + std::to_string(col); };
  auto pointer = [&] {
    std::string p;
    for (const Frame& f : stack) {
      if (!f.object) {
        p += "/" + std::to_string(f.index);
        continue;
      }
      p += "/";
      for (char c : f.key) p += c == '~' ? std::string("~0") : c == '/' ? std::string("~1") : std::string(1, c);
    }
    return p;
  };
  for (std::size_t i = 0; i < text.size(); ++i) {
    const char c = text[i];
    ++col;
    if (c == '\n') ++line, col = 0;
    if (c == '"') {  // a string: a key where its object expects one
      std::size_t j = i + 1;
      while (j < text.size() && text[j] != '"') j += text[j] == '\\' ? 2 : 1;
      if (!stack.empty() && stack.back().object && stack.back().want_key) {
        Frame& f = stack.back();
        f.key = text.substr(i + 1, std::min(j, text.size()) - i - 1);
        f.want_key = false;
        if (std::find(f.keys.begin(), f.keys.end(), f.key) != f.keys.end())
          throw InputError(file, pointer(), "", "each key once in its object (repeated at line " + std::to_string(line) + ", column " +
                                                    std::to_string(col) + "; JSON would keep only its last value)");
        f.keys.push_back(f.key);
      }
      for (std::size_t k = i + 1; k < j && k < text.size(); ++k) ++col;
      i = j;  // the closing quote (or the end)
      ++col;
      continue;
    }
    if (c == '[' || c == '{') {
      if (static_cast<int>(stack.size()) >= kMaxJsonDepth)
        throw InputError(where() + ": invalid JSON (nested deeper than " + std::to_string(kMaxJsonDepth) + " levels)");
      stack.push_back(Frame{c == '{', {}, {}, 0, true});
    } else if (c == ']' || c == '}') {
      if (!stack.empty()) stack.pop_back();
    } else if (c == ',' && !stack.empty()) {
      Frame& f = stack.back();
      if (f.object) f.want_key = true;
      else ++f.index;
    }
  }
}

}  // namespace dmi
