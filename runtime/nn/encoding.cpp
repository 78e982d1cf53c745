#include "nn/encoding.h"

#include <cmath>
#include <cstdio>
#include <deque>
#include <set>
#include <stdexcept>

#include "gl/shader_source.h"
#include "io/text.h"
#include "nn/registry_name.h"

namespace sn::nn {

std::vector<EncodingDef> builtin_encodings();  // nn/encoding_builtin.cpp, in BuiltinEncoding order

namespace {

// A deque: handles and references stay valid as definitions are added.
using Defs = std::deque<EncodingDef>;

int lookup(const Defs& defs, const std::string& name) {
  for (std::size_t i = 0; i < defs.size(); ++i)
    if (!defs[i].replaced && defs[i].name == name) return int(i);
  return -1;
}

// Whether two definitions encode every input they accept alike (their twins may differ: they are
// the oracle's and the cpu backend's, held to the GLSL at definition).
bool same_function(const EncodingDef& a, const EncodingDef& b) {
  if (a.glsl != b.glsl || a.count != b.count || a.count_min != b.count_min || a.count_max != b.count_max ||
      a.count_default != b.count_default || a.input_width != b.input_width ||
      a.has_include_input != b.has_include_input || a.include_input_default != b.include_input_default ||
      a.has_range != b.has_range)
    return false;
  for (int w = 1; w <= 4; ++w)
    for (int n = a.count.empty() ? 0 : a.count_min; n <= (a.count.empty() ? 0 : a.count_max); ++n)
      for (bool keep : {false, true})
        if (a.out_width(w, n, keep) != b.out_width(w, n, keep)) return false;
  return true;
}

// The one way into the registry, for built-ins and user definitions alike.
int add(Defs& defs, EncodingDef def, bool builtin) {
  if (!valid_registry_name(def.name))
    throw std::invalid_argument("encoding name '" + def.name + "': use lower-case letters, digits and _ (at most 40)");
  if (def.glsl.empty() || !def.f || !def.out_width)
    throw std::invalid_argument("encoding '" + def.name + "' needs its GLSL, its twin and its output width");
  if (!def.count.empty() && !(def.count_min >= 1 && def.count_min <= def.count_default && def.count_default <= def.count_max))
    throw std::invalid_argument("encoding '" + def.name + "': its " + def.count + " range is empty or misses its default");
  const int at = lookup(defs, def.name);
  if (at >= 0) {
    if (at < int(BuiltinEncoding::count))
      throw std::invalid_argument("encoding '" + def.name + "' is built in; choose another name");
    if (!builtin) {  // a script run again (live mode) defines it anew
      if (same_function(defs[std::size_t(at)], def)) {
        defs[std::size_t(at)] = std::move(def);
        return at;
      }
      defs[std::size_t(at)].replaced = true;  // kept for the networks built with it
    }
  }
  defs.push_back(std::move(def));
  return int(defs.size()) - 1;
}

Defs& registry() {
  static Defs defs = [] {
    Defs d;
    for (auto& def : builtin_encodings()) add(d, std::move(def), true);
    return d;
  }();
  return defs;
}

// The known range of a G-buffer attribute's components, for oneblob's default.
bool attribute_range(const std::string& input, double* lo, double* hi) {
  if (input == "normal" || input == "view" || input == "tangent" || input == "bitangent") {
    *lo = -1, *hi = 1;
    return true;
  }
  if (input == "uv" || input == "base_color") {
    *lo = 0, *hi = 1;
    return true;
  }
  return false;
}

}  // namespace

// ---- InputEncoding ----

int InputEncoding::out_width() const { return encoding_def(kind).out_width(width, n, include_input); }

bool InputEncoding::operator==(const InputEncoding& o) const {
  return input == o.input && offset == o.offset && width == o.width && kind == o.kind && n == o.n &&
         include_input == o.include_input && lo == o.lo && hi == o.hi;
}

std::string InputEncoding::describe() const {
  const EncodingDef& d = encoding_def(kind);
  std::string s = input + ": " + d.name;
  if (!d.count.empty()) s.append(" ").append(std::to_string(n));
  if (d.has_include_input && include_input != d.include_input_default) s += include_input ? " + input" : " - input";
  if (d.has_range) s += " on [" + io::number_text(lo) + ", " + io::number_text(hi) + "]";
  return s;
}

// ---- the registry ----

Encoding register_encoding(EncodingDef def) { return Encoding(add(registry(), std::move(def), false)); }

void unregister_encoding(Encoding e, const EncodingDef* previous, Encoding before) {
  Defs& defs = registry();
  if (is_builtin(e) || e.id < 0 || std::size_t(e.id) >= defs.size())
    throw std::logic_error("unregister_encoding: not a user definition");
  if (previous && e == before) {  // it had taken the earlier definition's place
    defs[std::size_t(e.id)] = *previous;
    return;
  }
  if (std::size_t(e.id) + 1 != defs.size()) throw std::logic_error("unregister_encoding: only the last definition can be removed");
  defs.pop_back();
  if (previous) defs[std::size_t(before.id)].replaced = false;  // the name finds it again
}

bool is_builtin(Encoding e) { return e.id >= 0 && e.id < int(BuiltinEncoding::count); }

bool single_threaded(const std::vector<InputEncoding>& encodings) {
  for (const auto& e : encodings)
    if (encoding_def(e.kind).caller_thread) return true;
  return false;
}

const EncodingDef& encoding_def(Encoding e) {
  const Defs& defs = registry();
  if (e.id < 0 || std::size_t(e.id) >= defs.size()) throw std::out_of_range("no encoding with id " + std::to_string(e.id));
  return defs[std::size_t(e.id)];
}

const char* encoding_name(Encoding e) { return encoding_def(e).name.c_str(); }

std::vector<std::string> encoding_names() {
  std::vector<std::string> names;
  for (const auto& d : registry())
    if (!d.replaced) names.push_back(d.name);
  return names;
}

bool find_encoding(const std::string& name, Encoding* out) {
  const int at = lookup(registry(), name);
  if (at < 0) return false;
  *out = Encoding(at);
  return true;
}

Encoding parse_encoding(const std::string& name) {
  Encoding e;
  if (find_encoding(name, &e)) return e;
  throw std::invalid_argument("unknown encoding '" + name + "' (valid: " + io::join(encoding_names()) + ")");
}

InputEncoding default_encoding(Encoding kind, const std::string& input, int offset, int width) {
  const EncodingDef& d = encoding_def(kind);
  InputEncoding e;
  e.input = input;
  e.offset = offset;
  e.width = width;
  e.kind = kind;
  e.n = d.count.empty() ? 0 : d.count_default;
  e.include_input = d.has_include_input && d.include_input_default;
  if (d.has_range && !attribute_range(input, &e.lo, &e.hi)) e.lo = e.hi = std::nan("");
  return e;
}

void check(const InputEncoding& e) {
  const EncodingDef& d = encoding_def(e.kind);
  const std::string who = "encoding '" + d.name + "' of input '" + e.input + "'";
  if (d.input_width > 0 && e.width != d.input_width)
    throw std::invalid_argument(who + ": needs an input of " + std::to_string(d.input_width) + " components (" +
                                (d.input_width == 3 ? "a direction such as normal or view" : "") + "), '" + e.input +
                                "' has " + std::to_string(e.width));
  if (e.width < 1 || e.width > 4)
    throw std::invalid_argument(who + ": an encoded input has 1..4 components, '" + e.input + "' has " +
                                std::to_string(e.width));
  if (!d.count.empty() && (e.n < d.count_min || e.n > d.count_max))
    throw std::invalid_argument(who + ": " + d.count + " must be " + std::to_string(d.count_min) + ".." +
                                std::to_string(d.count_max) + ", got " + std::to_string(e.n));
  if (d.has_range) {
    if (std::isnan(e.lo) && std::isnan(e.hi))
      throw std::invalid_argument(who + ": '" + e.input + "' has no fixed range; give it as range = {min, max}");
    if (!(std::isfinite(e.lo) && std::isfinite(e.hi) && e.lo < e.hi))
      throw std::invalid_argument(who + ": range must be two finite numbers {min, max} with min < max, got {" + io::number_text(e.lo) +
                                  ", " + io::number_text(e.hi) + "}");
  }
}

// ---- encoding rows ----

int encoded_width(const std::vector<InputEncoding>& encodings, int inputs) {
  int w = inputs;
  for (const auto& e : encodings) w += e.out_width() - e.width;
  return w;
}

void encode_row(const std::vector<InputEncoding>& encodings, int inputs, const double* x, double* out) {
  int at = 0, o = 0;
  for (const auto& e : encodings) {
    while (at < e.offset) out[o++] = x[at++];
    const EncodingDef& d = encoding_def(e.kind);
    double v[4] = {0, 0, 0, 0};
    for (int c = 0; c < e.width; ++c) v[c] = x[e.offset + c];
    const int n = d.out_width(e.width, e.n, e.include_input);
    if (d.f_row) {
      d.f_row(e, v, out + o);
      o += n;
    } else {
      for (int j = 0; j < n; ++j) out[o++] = d.f(e, v, j);
    }
    at = e.offset + e.width;
  }
  while (at < inputs) out[o++] = x[at++];
}

void encode_rows(const std::vector<InputEncoding>& encodings, int inputs, const float* x, std::size_t rows, float* out) {
  const int w = encoded_width(encodings, inputs);
  std::vector<double> in(static_cast<std::size_t>(inputs)), enc(static_cast<std::size_t>(w));
  for (std::size_t r = 0; r < rows; ++r) {
    for (int i = 0; i < inputs; ++i) in[std::size_t(i)] = x[r * std::size_t(inputs) + std::size_t(i)];
    encode_row(encodings, inputs, in.data(), enc.data());
    for (int i = 0; i < w; ++i) out[r * std::size_t(w) + std::size_t(i)] = float(enc[std::size_t(i)]);
  }
}

std::vector<float> encode_rows(const std::vector<InputEncoding>& encodings, int inputs, const float* x,
                               std::size_t rows) {
  std::vector<float> out(rows * std::size_t(encoded_width(encodings, inputs)));
  encode_rows(encodings, inputs, x, rows, out.data());
  return out;
}

// ---- GLSL ----

std::string encoding_glsl_function(Encoding e) { return "sn_enc_" + encoding_def(e).name; }

std::string encoding_glsl_source(const std::vector<InputEncoding>& encodings, int inputs) {
  std::string src;
  std::set<int> defined;
  for (const auto& e : encodings) {
    if (!defined.insert(e.kind.id).second) continue;
    const EncodingDef& d = encoding_def(e.kind);
    // The body starts on the header's line: an error's line number counts within the given text.
    src += "float " + encoding_glsl_function(e.kind) + "(vec4 x, int w, int j, int n, bool keep, vec2 range) { " + d.glsl +
           "\n}\n";
  }
  const int w = encoded_width(encodings, inputs), w4 = (w + 3) / 4;
  const std::string raw = std::to_string(inputs);
  std::vector<std::string> comps;
  std::string code;
  int at = 0;
  auto x = [](int i) { return "x[" + std::to_string(i) + "]"; };
  for (std::size_t k = 0; k < encodings.size(); ++k) {
    const InputEncoding& e = encodings[k];
    while (at < e.offset) comps.push_back(x(at++));
    const std::string v = std::string("g").append(std::to_string(k));
    code += "  vec4 " + v + " = vec4(";
    for (int c = 0; c < 4; ++c) code += (c ? ", " : "") + (c < e.width ? x(e.offset + c) : std::string("0.0"));
    code += ");\n";
    const std::string args = ", " + std::to_string(e.width) + ", ", tail = ", " + std::to_string(e.n) + ", " +
                                                                      (e.include_input ? "true" : "false") + ", vec2(" +
                                                                      gl::float_literal(e.lo) + ", " + gl::float_literal(e.hi) + "))";
    for (int j = 0; j < e.out_width(); ++j)
      comps.push_back(encoding_glsl_function(e.kind) + "(" + v + args + std::to_string(j) + tail);
    at = e.offset + e.width;
  }
  while (at < inputs) comps.push_back(x(at++));
  while (int(comps.size()) < 4 * w4) comps.push_back("0.0");
  src += "void mlp_encode(float x[" + raw + "], out vec4 e[" + std::to_string(w4) + "]) {\n" + code;
  for (int q = 0; q < w4; ++q)
    src += "  e[" + std::to_string(q) + "] = vec4(" + comps[4 * q] + ", " + comps[4 * q + 1] + ", " + comps[4 * q + 2] +
           ", " + comps[4 * q + 3] + ");\n";
  return src + "}\n";
}

}  // namespace sn::nn
