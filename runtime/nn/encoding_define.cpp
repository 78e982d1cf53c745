#include "nn/encoding_define.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <vector>

#include "gl/program.h"
#include "io/text.h"
#include "nn/gl_forward.h"
#include "nn/mlp_spec.h"

namespace sn::nn {

namespace {

// Inputs the checks encode: components spread over [-m, m], off the simple fractions where a
// mistake could hide (0, +-0.5). The twin's own checks take m = 0.9 (directions and uv); the GLSL
// is compared with it far beyond as well, since positions, world positions and varied parameters
// leave [-1, 1] (a GLSL that clamped to [-1, 1] and a twin that did not were taken, and the cpu
// backend, which encodes with the twin, trained another function than gl).
std::vector<double> sample_rows(int width, int rows, double m = 0.9) {
  std::vector<double> x;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < width; ++c) x.push_back(m * std::sin(1.7 * r + 2.3 * c + 0.41));
  return x;
}
constexpr double kWideMagnitudes[] = {3, 30, 300};

// The encoding of one input of `width` components with count n and include_input keep; a range
// of [-1, 1] where the encoding takes one.
InputEncoding instance(Encoding kind, const EncodingDef& d, int width, int n, bool keep) {
  InputEncoding e;
  e.input = "x";
  e.width = width;
  e.kind = kind;
  e.n = n;
  e.include_input = keep;
  if (d.has_range) e.lo = -1, e.hi = 1;
  return e;
}

std::string case_of(const EncodingDef& d, const InputEncoding& e) {
  std::string s = "an input of " + std::to_string(e.width) + " component" + (e.width > 1 ? "s" : "");
  if (!d.count.empty()) s += ", " + d.count + " = " + std::to_string(e.n);
  if (d.has_include_input) s += std::string(", include_input = ") + (e.include_input ? "true" : "false");
  return s;
}

std::vector<int> widths(const EncodingDef& d) {
  return d.input_width > 0 ? std::vector<int>{d.input_width} : std::vector<int>{1, 2, 3, 4};
}

// Every output of the twin for one input (f_row where the encoding has one, else f per output).
void twin_row(const InputEncoding& e, const double* x, double* out) { encode_row({e}, e.width, x, out); }

std::string components(const double* x, int w) {
  std::string s;
  for (int c = 0; c < w; ++c) s += (c ? ", " : "") + io::number_text(x[c]);
  return "{" + s + "}";
}

// Every width, the count's ends and default, both include_input settings: the output count is
// 1..256 and the twin runs on sample rows (f_row refuses outputs that are not finite, at
// definition and on the data alike: lua/wrap_encoding.cpp).
void check_twin(Encoding kind, const EncodingDef& d) {
  std::vector<int> counts = {0};
  if (!d.count.empty()) counts = {d.count_min, d.count_default, d.count_max};
  std::vector<bool> keeps = {d.has_include_input && d.include_input_default};
  if (d.has_include_input) keeps = {false, true};
  for (int w : widths(d))
    for (int n : counts)
      for (bool keep : keeps) {
        const InputEncoding e = instance(kind, d, w, n, keep);
        const int outputs = d.out_width(w, n, keep);
        if (outputs < 1 || outputs > 256)
          throw std::invalid_argument("encoding '" + d.name + "': outputs for " + case_of(d, e) + " is " +
                                      std::to_string(outputs) + "; it must be 1..256");
        const std::vector<double> x = sample_rows(w, 8);
        std::vector<double> out(static_cast<std::size_t>(outputs));
        for (int r = 0; r < 8; ++r) twin_row(e, x.data() + r * w, out.data());
      }
}

// The GLSL against the twin: at the default count and include_input for an input of the
// required width, else of 1 and 3 components; at the count's ends and the other include_input
// for the last of those (one program each). A GLSL right at the default count alone was taken,
// and cpu and gl then trained other functions.
void check_glsl(Encoding kind, const EncodingDef& d) {
  const std::vector<int> ws = d.input_width > 0 ? std::vector<int>{d.input_width} : std::vector<int>{1, 3};
  const int n0 = d.count.empty() ? 0 : d.count_default;
  const bool keep0 = d.has_include_input && d.include_input_default;
  struct Case {
    int w, n;
    bool keep;
  };
  std::vector<Case> cases;
  for (int w : ws) cases.push_back({w, n0, keep0});
  if (!d.count.empty()) {
    if (d.count_min != n0) cases.push_back({ws.back(), d.count_min, keep0});
    if (d.count_max != n0) cases.push_back({ws.back(), d.count_max, keep0});
  }
  if (d.has_include_input) cases.push_back({ws.back(), n0, !keep0});
  for (const Case& c : cases) {
    const int w = c.w;
    const InputEncoding e = instance(kind, d, w, c.n, c.keep);
    MlpSpec spec;
    spec.inputs = w;
    spec.encodings = {e};
    spec.hidden = {1};
    spec.outputs = 1;
    const int near_rows = 16, outputs = e.out_width();
    std::vector<double> xd = sample_rows(w, near_rows);
    for (double m : kWideMagnitudes) {
      const std::vector<double> wide = sample_rows(w, 8, m);
      xd.insert(xd.end(), wide.begin(), wide.end());
    }
    const int rows = int(xd.size()) / w;
    const std::vector<float> x(xd.begin(), xd.end());
    std::vector<float> got;
    try {
      gl::NoProgramFallback strict;  // in live mode too: never the last good program of the same name
      got = gl_encode(spec, x);
    } catch (const std::exception& ex) {
      // The log names the include; a person wrote the text at the defining script line.
      std::string log = ex.what();
      const std::string include = "mlp/enc_net.glsl";
      for (std::size_t at = log.find(include); at != std::string::npos; at = log.find(include, at + d.origin.size()))
        log.replace(at, include.size(), d.origin);
      throw std::invalid_argument("encoding '" + d.name + "': its GLSL does not compile:\n" + log);
    }
    std::vector<double> want(static_cast<std::size_t>(outputs)), row(static_cast<std::size_t>(w));
    for (int r = 0; r < rows; ++r) {
      for (int k = 0; k < w; ++k) row[std::size_t(k)] = double(x[std::size_t(r * w + k)]);  // what the GPU read
      if (r < near_rows) {
        twin_row(e, row.data(), want.data());
      } else {
        // Beyond [-1, 1] the twin need not be defined (acos of a direction's component): only
        // where it is are the two compared; a row of the data it fails on is an error there.
        try {
          twin_row(e, row.data(), want.data());
        } catch (const std::exception&) {
          continue;
        }
      }
      for (int j = 0; j < outputs; ++j) {
        const double a = got[std::size_t(r * outputs + j)], b = want[std::size_t(j)];
        if (!twin_agrees(a, b, row.data(), w))
          throw std::invalid_argument("encoding '" + d.name + "': its GLSL gives " + io::number_text(a) + " as output " +
                                      std::to_string(j + 1) + " of " + components(row.data(), w) + " (" + case_of(d, e) +
                                      "), its Lua twin " + io::number_text(b));
      }
    }
  }
}

// "t12.lua:2" of a user's definition, whose origin reads "t12.lua:2 encoding sq"; empty when the
// line is not known.
std::string defined_at(const EncodingDef& d) {
  const std::string tail = "encoding " + d.name;
  if (d.origin.size() <= tail.size() || d.origin.compare(d.origin.size() - tail.size(), tail.size(), tail) != 0)
    return "";
  std::string at = d.origin.substr(0, d.origin.size() - tail.size());
  while (!at.empty() && at.back() == ' ') at.pop_back();
  return at;
}

}  // namespace

Encoding define_encoding(EncodingDef def) {
  if (!def.f_row) throw std::invalid_argument("encoding '" + def.name + "' needs its twin");
  std::optional<EncodingDef> previous;
  Encoding old;
  if (find_encoding(def.name, &old) && !is_builtin(old)) previous = encoding_def(old);
  const Encoding kind = register_encoding(std::move(def));  // checks the name and the count's range
  try {
    check_definition(kind);
  } catch (...) {
    unregister_encoding(kind, previous ? &*previous : nullptr, old);
    throw;
  }
  return kind;
}

void check_definition(Encoding kind) {
  check_twin(kind, encoding_def(kind));
  check_glsl(kind, encoding_def(kind));
}

bool twin_agrees(double glsl, double twin, const double* x, int width) {
  // Float cannot hold the twin's value: the cpu backend's rows hold the same infinity (encode_rows).
  if (std::isinf(float(twin))) return glsl == double(float(twin));
  double m = 1;
  for (int c = 0; c < width; ++c) m = std::max(m, std::fabs(x[c]));
  // Float rounding grows with the input's magnitude: a user's plain cos(2^k pi x) used a fifth of
  // this at 0.9 and at 300 alike (llvmpipe); the built-ins, which reduce exactly, under 0.5%.
  return std::fabs(glsl - twin) <= 1e-4 * (1 + std::fabs(twin)) * m;
}

void check_on_rows(const std::vector<InputEncoding>& encodings, int inputs, const float* x, const float* encoded,
                   std::size_t rows, const char* what) {
  bool user = false;
  for (const auto& e : encodings) user = user || !is_builtin(e.kind);
  if (!user || rows == 0) return;
  MlpSpec spec;
  spec.inputs = inputs;
  spec.encodings = encodings;
  spec.hidden = {1};
  spec.outputs = 1;
  const std::size_t w = std::size_t(encoded_width(encodings, inputs));
  constexpr std::size_t kBlock = 65536;
  for (std::size_t first = 0; first < rows; first += kBlock) {
    const std::size_t count = std::min(kBlock, rows - first);
    const std::vector<float> got =
        gl_encode(spec, std::vector<float>(x + first * std::size_t(inputs), x + (first + count) * std::size_t(inputs)));
    for (std::size_t r = 0; r < count; ++r) {
      const float* raw = x + (first + r) * std::size_t(inputs);
      int at = 0, col = 0;
      for (const auto& e : encodings) {
        col += e.offset - at;
        const int outputs = e.out_width();
        if (!is_builtin(e.kind)) {
          double in[4] = {0, 0, 0, 0};
          for (int c = 0; c < e.width; ++c) in[c] = raw[e.offset + c];
          for (int j = 0; j < outputs; ++j) {
            const double a = got[r * w + std::size_t(col + j)], b = encoded[(first + r) * w + std::size_t(col + j)];
            if (twin_agrees(a, b, in, e.width)) continue;
            const EncodingDef& d = encoding_def(e.kind);
            const std::string at_line = defined_at(d);
            throw std::invalid_argument(
                "encoding '" + d.name + "'" + (at_line.empty() ? "" : " (defined at " + at_line + ")") + " of input '" +
                e.input + "': on " + what + " " + std::to_string(first + r + 1) + ", " + e.input + " = " +
                components(in, e.width) + ", its GLSL gives " + io::number_text(a) + " as output " + std::to_string(j + 1) +
                ", its Lua twin " + io::number_text(b) +
                "; the cpu backend trains on the twin's values, gl on the GLSL's: make them agree for inputs like this one");
          }
        }
        col += outputs;
        at = e.offset + e.width;
      }
    }
  }
}

}  // namespace sn::nn
