// NumPy .npy files holding one 2-D float32 array: written exactly as numpy.save writes one
// (format 1.0, dtype '<f4', C order, header padded so the data starts on a 64-byte boundary),
// read with every check a truncated or foreign file needs.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace sn::io {

// The header numpy.save writes for a (rows, cols) '<f4' array: magic, version 1.0, length,
// the dict (with numpy's spare room for growing the first axis), spaces, '\n'.
std::string npy_header(std::size_t rows, std::size_t cols);

// Header and data of a row-major (rows, cols) array.
std::string npy_bytes(const float* data, std::size_t rows, std::size_t cols);

struct NpyArray {
  std::size_t rows = 0, cols = 0;
  std::vector<float> data;  // row-major
};

// Parses a file's bytes; `name` starts every message ("x.npy: dtype '<f8' is not ...").
// Accepts format versions 1.0, 2.0 and 3.0 holding a 2-D, C-order, '<f4' array whose data
// fills the rest of the file exactly.
NpyArray parse_npy(const std::string& bytes, const std::string& name);

}  // namespace sn::io
