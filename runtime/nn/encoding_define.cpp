#include "nn/encoding_define.h"

#include <cmath>
#include <cstdio>
#include <optional>
#include <stdexcept>
#include <vector>

#include "io/text.h"
#include "nn/gl_forward.h"
#include "nn/mlp_spec.h"

namespace sn::nn {

namespace {

// Inputs the checks encode: components spread over [-0.9, 0.9], off the simple fractions where
// a mistake could hide (0, +-0.5).
std::vector<double> sample_rows(int width, int rows) {
  std::vector<double> x;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < width; ++c) x.push_back(0.9 * std::sin(1.7 * r + 2.3 * c + 0.41));
  return x;
}

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
        for (int r = 0; r < 8; ++r) d.f_row(e, x.data() + r * w, out.data());
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
    const int rows = 16, outputs = e.out_width();
    const std::vector<double> xd = sample_rows(w, rows);
    const std::vector<float> x(xd.begin(), xd.end());
    std::vector<float> got;
    try {
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
      for (int c = 0; c < w; ++c) row[std::size_t(c)] = double(x[std::size_t(r * w + c)]);  // what the GPU read
      d.f_row(e, row.data(), want.data());
      for (int j = 0; j < outputs; ++j) {
        const double a = got[std::size_t(r * outputs + j)], b = want[std::size_t(j)];
        if (!(std::fabs(a - b) <= 1e-4 * (1 + std::fabs(b)))) {
          std::string in;
          for (int c = 0; c < w; ++c) in += (c ? ", " : "") + io::number_text(row[std::size_t(c)]);
          throw std::invalid_argument("encoding '" + d.name + "': its GLSL gives " + io::number_text(a) + " as output " +
                                      std::to_string(j + 1) + " of {" + in + "} (" + case_of(d, e) + "), its Lua twin " +
                                      io::number_text(b));
        }
      }
    }
  }
}

}  // namespace

Encoding define_encoding(EncodingDef def) {
  if (!def.f_row) throw std::invalid_argument("encoding '" + def.name + "' needs its twin");
  std::optional<EncodingDef> previous;
  Encoding old;
  if (find_encoding(def.name, &old) && !is_builtin(old)) previous = encoding_def(old);
  const Encoding kind = register_encoding(std::move(def));  // checks the name and the count's range
  try {
    check_twin(kind, encoding_def(kind));
    check_glsl(kind, encoding_def(kind));
  } catch (...) {
    unregister_encoding(kind, previous ? &*previous : nullptr);
    throw;
  }
  return kind;
}

}  // namespace sn::nn
