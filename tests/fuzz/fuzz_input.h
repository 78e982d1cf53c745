// What every fuzz target shares: the loaders under test read files, so an input is written to a
// scratch file first (they are fuzzed through the same path a user's file takes), and inputs
// that hold several files are split at a separator line.
#pragma once
#include <cstddef>
#include <cstdint>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "io/temp_dir.h"

namespace sn::fuzz {

// One scratch folder per process, so parallel fuzzing jobs (-jobs=N) do not share files;
// removed when the process exits.
inline const std::string& scratch_dir() {
  static const io::TempDir dir("fuzz");
  return dir.path();
}

// Writes `bytes` to scratch_dir()/name and returns the path.
inline std::string scratch_file(const std::string& name, const void* bytes, std::size_t size) {
  std::string path = scratch_dir() + "/" + name;
  std::ofstream f(path, std::ios::binary | std::ios::trunc);
  f.write(static_cast<const char*>(bytes), std::streamsize(size));
  if (!f.flush()) throw std::runtime_error("fuzz: cannot write " + path);
  return path;
}

// The parts of an input holding several files, separated by lines "--8<--".
inline std::vector<std::string> split_parts(const uint8_t* data, std::size_t size) {
  static const std::string sep = "\n--8<--\n";
  std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> parts;
  std::size_t at = 0;
  for (std::size_t hit; (hit = text.find(sep, at)) != std::string::npos; at = hit + sep.size())
    parts.push_back(text.substr(at, hit - at));
  parts.push_back(text.substr(at));
  return parts;
}

}  // namespace sn::fuzz
