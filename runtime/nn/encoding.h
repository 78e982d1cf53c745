// Input encodings as plug-ins, the way activations are (nn/activation.h): one registry maps a
// name to everything a backend needs, the GLSL of one output component and a double-precision
// twin of it. The built-ins register themselves (nn/encoding_builtin.cpp) through
// register_encoding(), the call a user's definition would go through.
//
// An encoding replaces one input group (a G-buffer attribute such as "uv", or a condition) by a
// fixed function of it: it has no trainable parameters, so no gradient flows through it. The
// network's first layer sees the raw inputs in their order with every encoded group replaced
// by its encoding's outputs (MlpSpec::width(0) is that encoded width).
//
// Each encoding takes at most one count (frequency's and triangle_wave's bands, oneblob's bins,
// sh's degree), and optionally whether the raw components are kept in front of the encoded
// ones (include_input) and the range the input lies in (oneblob's range).
#pragma once
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace sn::nn {

// A registered encoding, by its index in the registry. The built-ins have fixed ids.
struct Encoding {
  int id = 0;
  Encoding() = default;
  explicit Encoding(int i) : id(i) {}
  bool operator==(Encoding o) const { return id == o.id; }
  bool operator!=(Encoding o) const { return id != o.id; }
  static const Encoding identity, frequency, oneblob, sh, triangle_wave;
};

enum class BuiltinEncoding : int { identity, frequency, oneblob, sh, triangle_wave, count };

inline const Encoding Encoding::identity{int(BuiltinEncoding::identity)};
inline const Encoding Encoding::frequency{int(BuiltinEncoding::frequency)};
inline const Encoding Encoding::oneblob{int(BuiltinEncoding::oneblob)};
inline const Encoding Encoding::sh{int(BuiltinEncoding::sh)};
inline const Encoding Encoding::triangle_wave{int(BuiltinEncoding::triangle_wave)};

// One input group's encoding, as a network stores it (MlpSpec::encodings).
struct InputEncoding {
  std::string input;            // the input's name ("uv"): messages, net:spec(), checkpoints
  int offset = 0, width = 0;    // its raw columns [offset, offset + width) of an input row
  Encoding kind;
  int n = 0;                    // the count: bands, bins or degree (0 for identity)
  bool include_input = false;   // the raw components come first (frequency, triangle_wave)
  double lo = 0, hi = 1;        // the range the input lies in (oneblob)

  int out_width() const;        // the encoding's outputs
  bool operator==(const InputEncoding& o) const;
  bool operator!=(const InputEncoding& o) const { return !(*this == o); }
  // "uv: frequency 8", "normal: sh 4", "roughness: oneblob 16 on [0.05, 1]"; include_input is
  // written when it differs from the encoding's default ("+ input" / "- input").
  std::string describe() const;
};

struct EncodingDef {
  std::string name;
  // The count's option name ("bands", "bins", "degree"; empty: none), range and default.
  std::string count;
  int count_min = 0, count_max = 0, count_default = 0;
  int input_width = 0;  // the width the input must have (sh: 3, a direction); 0: any (1..4)
  bool has_include_input = false, include_input_default = false;
  bool has_range = false;  // takes range = {lo, hi}
  // Outputs for an input of `width` components.
  std::function<int(int width, int n, bool include_input)> out_width;
  // GLSL body of `float FN(vec4 x, int w, int j, int n, bool keep, vec2 range)`: output j of the
  // encoding of x (its w components; those past w are 0), count n, include_input keep. The call
  // sites pass literals, so the branches on them fold away.
  std::string glsl;
  // The double twin of the same: output j of x[0..width).
  std::function<double(const InputEncoding& e, const double* x, int j)> f;
  // Optional: every output at once (out[0..out_width)), the same values as f, for speed (the cpu
  // backend encodes whole datasets with it: oneblob shares each bin edge's CDF between two bins).
  std::function<void(const InputEncoding& e, const double* x, double* out)> f_row;
  std::string origin;  // where errors in the GLSL point: "built-in encoding frequency"
  // What identifies a user's twin (its bytecode and the values it closes over, taken at
  // definition: lua/binding.h function_fingerprint), for its key: the cpu backend trains on the
  // twin's values, so a twin changed alone is a new definition.
  std::string twin_fingerprint;
  // The twins may run only on the thread that called into shadenet (a user's Lua function): rows
  // of such an encoding are encoded on that thread alone (single_threaded()).
  bool caller_thread = false;
  // A later definition of the name replaced this one: the name finds that one now, and networks
  // built before keep this one (they hold the handle).
  bool replaced = false;
};

// Registers a definition (its name must be new, or name an earlier user definition, which it
// replaces); returns its handle. Throws for a bad name or a clash with a built-in.
// A network holds its encodings by handle: one that replaces an earlier definition with another
// function (GLSL, count, widths) gets a handle of its own, so networks built before keep encoding
// their inputs as they were built (and trained) to; the same again (a script run again) keeps the
// earlier handle.
Encoding register_encoding(EncodingDef def);
// Undoes the last register_encoding of a user definition that failed its checks
// (nn/encoding_define.h). `previous` is the definition the name found before (null: none) and
// `before` its handle: put back in its place, or found by the name again once the entry the
// failed definition added is removed.
void unregister_encoding(Encoding e, const EncodingDef* previous, Encoding before);
const EncodingDef& encoding_def(Encoding e);
const char* encoding_name(Encoding e);
bool is_builtin(Encoding e);  // shipped with shadenet (not a user's definition)
// Every registered name, in registry order.
std::vector<std::string> encoding_names();
bool find_encoding(const std::string& name, Encoding* out);
// Throws "unknown encoding 'x' (valid: identity, frequency, oneblob, sh, triangle_wave)".
Encoding parse_encoding(const std::string& name);

// The encoding `kind` of input `input` (raw columns offset.. offset + width) with the
// encoding's defaults: count, include_input, and for oneblob the range of the attribute where
// it is known (unit vectors [-1, 1]; uv, base_color [0, 1]; lo = hi = NaN otherwise, which
// check() refuses until a range is set).
InputEncoding default_encoding(Encoding kind, const std::string& input, int offset, int width);
// Throws std::invalid_argument naming the input, the encoding and the valid range of what is
// wrong: a count out of range, sh on an input that is not 3 wide, a range that is not finite
// and increasing, an input wider than 4.
void check(const InputEncoding& e);

// True when some encoding's twin must run on the calling thread (EncodingDef::caller_thread):
// rows are then encoded by that thread alone.
bool single_threaded(const std::vector<InputEncoding>& encodings);

// The encoded width of `inputs` raw inputs under `encodings` (disjoint groups).
int encoded_width(const std::vector<InputEncoding>& encodings, int inputs);
// One row: raw x[0..inputs) -> out[0..encoded_width) in double (the oracle's, the cpu backend's).
void encode_row(const std::vector<InputEncoding>& encodings, int inputs, const double* x, double* out);
// `rows` rows of floats, encoded in double and rounded once: rows x encoded_width floats.
std::vector<float> encode_rows(const std::vector<InputEncoding>& encodings, int inputs, const float* x,
                               std::size_t rows);
void encode_rows(const std::vector<InputEncoding>& encodings, int inputs, const float* x, std::size_t rows, float* out);

// GLSL of the encodings a network uses and of
//   void mlp_encode(float x[RAW], out vec4 e[ENC4])
// that fills the first layer's input vec4s (zeros in the padding) from one raw input row, RAW =
// inputs, ENC4 = encoded width / 4 rounded up. Every index is a literal (straight-line code).
std::string encoding_glsl_source(const std::vector<InputEncoding>& encodings, int inputs);
// The GLSL function name of an encoding: sn_enc_<name>.
std::string encoding_glsl_function(Encoding e);

}  // namespace sn::nn
