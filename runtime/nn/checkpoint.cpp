#include "nn/checkpoint.h"

#include <unistd.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <stdexcept>

#include "io/atomic_write.h"
#include "io/hash.h"
#include "io/text.h"
#include "io/read_file.h"

namespace sn::nn {

namespace {

constexpr char kMagic[8] = {'s', 'n', 'm', 'l', 'p', '\r', '\n', '\x1a'};
constexpr std::size_t kHeader = 24;

// Little-endian writer/reader (this machine is little-endian; memcpy keeps it explicit).
static_assert(std::endian::native == std::endian::little, "checkpoint I/O assumes a little-endian host");

struct Writer {
  std::string out;
  template <class T>
  void put(T v) {
    char b[sizeof(T)];
    std::memcpy(b, &v, sizeof(T));
    out.append(b, sizeof(T));
  }
  void str(const std::string& s) {
    put(uint32_t(s.size()));
    out += s;
  }
};

struct Reader {
  const std::string& in;
  std::size_t pos;
  const std::string& path;
  template <class T>
  T get(const char* what) {
    need(sizeof(T), what);
    T v;
    std::memcpy(&v, in.data() + pos, sizeof(T));
    pos += sizeof(T);
    return v;
  }
  std::string str(const char* what) {
    uint32_t n = get<uint32_t>(what);
    need(n, what);
    std::string s = in.substr(pos, n);
    pos += n;
    return s;
  }
  void need(std::size_t n, const char* what) {
    if (in.size() - pos < n) throw std::runtime_error(path + ": checkpoint ends inside the " + what);
  }
};

// The first non-finite value of `v`, named as scripts index it ("" when all are finite).
std::string first_nonfinite(const MlpSpec& spec, const std::vector<float>& v) {
  for (std::size_t j = 0; j < v.size(); ++j)
    if (!std::isfinite(v[j]))
      return spec.param_name(j) + " (parameter " + std::to_string(j + 1) + " of " + std::to_string(v.size()) + ") is " +
             (std::isnan(v[j]) ? "NaN" : "infinite");
  return "";
}

}  // namespace

void save_checkpoint(const Mlp& net, const std::string& path) {
  net.spec.validate();
  if (net.params.size() != net.spec.param_count()) throw std::invalid_argument("save: parameter count does not match the spec");
  // A diverged network is not a checkpoint: it would load as NaN renders with nothing said.
  if (std::string bad = first_nonfinite(net.spec, net.params); !bad.empty())
    throw std::runtime_error("cannot save checkpoint " + path + ": the network's " + bad +
                             " (a diverged network; net:restore_best() or train it again)");
  if (net.best_epoch > 0)
    if (std::string bad = first_nonfinite(net.spec, net.best_params); !bad.empty())
      throw std::runtime_error("cannot save checkpoint " + path + ": the best-epoch snapshot's " + bad);
  Writer p;
  p.put(uint32_t(net.spec.inputs));
  p.put(uint32_t(net.spec.outputs));
  p.put(uint32_t(net.spec.hidden.size()));
  for (int w : net.spec.hidden) p.put(uint32_t(w));
  p.str(activation_name(net.spec.activation));
  p.put(double(net.spec.slope));
  p.str(activation_name(net.spec.output_activation));
  p.str(shading::color_space_name(net.spec.color));
  p.put(uint32_t(net.input_names.size()));
  for (const auto& n : net.input_names) p.str(n);
  p.put(uint64_t(net.trained_steps));
  p.put(uint64_t(net.params.size()));
  for (float v : net.params) p.put(v);
  const bool best = net.best_epoch > 0 && net.best_params.size() == net.params.size();
  p.put(uint32_t(best ? net.best_epoch : 0));
  if (best) {
    p.put(double(net.best_val_mse));
    for (float v : net.best_params) p.put(v);
  }
  // Optional trailing sections, each a tag and its data; a network that needs none ends here
  // (older files do, and still load).
  if (!net.conditions.empty()) {
    p.str("conditions");
    p.put(uint32_t(net.conditions.size()));
    for (const auto& c : net.conditions) {
      p.str(c.name);
      p.put(double(c.min));
      p.put(double(c.max));
      p.put(double(c.value));
    }
  }
  if (!net.spec.encodings.empty()) {
    p.str("encodings");
    p.put(uint32_t(net.spec.encodings.size()));
    for (const auto& e : net.spec.encodings) {
      p.str(e.input);
      p.put(uint32_t(e.offset));
      p.put(uint32_t(e.width));
      p.str(encoding_name(e.kind));
      p.put(uint32_t(e.n));
      p.put(uint8_t(e.include_input ? 1 : 0));
      p.put(double(e.lo));
      p.put(double(e.hi));
    }
  }
  std::vector<std::pair<std::string, std::string>> entries;
  for (Activation a : {net.spec.activation, net.spec.output_activation}) {
    const ActivationParam k = activation_def(a).param;
    if (k != ActivationParam::omega && k != ActivationParam::alpha) continue;  // slope has its own field
    char v[40];
    std::snprintf(v, sizeof v, "%.17g", net.spec.param(a));
    if (entries.empty() || entries.back().first != activation_param_name(k)) entries.emplace_back(activation_param_name(k), v);
  }
  // A user's activation travels by definition: its GLSL (the Lua twins cannot be saved).
  std::set<std::string> recorded;
  for (Activation a : {net.spec.activation, net.spec.output_activation}) {
    const ActivationDef& d = activation_def(a);
    if (d.simd >= 0 || !recorded.insert(d.name).second) continue;
    entries.emplace_back("activation " + d.name + " glsl", d.glsl);
    entries.emplace_back("activation " + d.name + " grad", d.grad);
  }
  // A user's encoding too: its GLSL.
  for (const auto& e : net.spec.encodings) {
    const EncodingDef& d = encoding_def(e.kind);
    const std::string key = "encoding " + d.name + " glsl";
    if (is_builtin(e.kind) || std::any_of(entries.begin(), entries.end(), [&](const auto& kv) { return kv.first == key; }))
      continue;
    entries.emplace_back(key, d.glsl);
  }
  if (!entries.empty()) {
    p.str("entries");
    p.put(uint32_t(entries.size()));
    for (const auto& [k, v] : entries) {
      p.str(k);
      p.str(v);
    }
  }

  Writer file;
  file.out.append(kMagic, sizeof kMagic);
  file.put(uint32_t(kCheckpointVersion));
  file.put(uint32_t(p.out.size()));
  file.put(io::fnv1a(p.out));
  file.out += p.out;

  io::write_file_atomic(path, file.out, "checkpoint");
}

Mlp load_checkpoint(const std::string& path) {
  // Regular files only, within the read limit (io/read_file.h): /dev/zero would be read forever.
  const std::string bytes = io::read_file(path, "checkpoint");
  if (bytes.size() < kHeader || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
    throw std::runtime_error(path + ": not a shadenet network checkpoint (bad magic)");
  Reader h{bytes, sizeof kMagic, path};
  const uint32_t version = h.get<uint32_t>("header");
  if (version != kCheckpointVersion)
    throw std::runtime_error(path + ": checkpoint format version " + std::to_string(version) + ", this build reads " +
                             std::to_string(kCheckpointVersion));
  const uint32_t size = h.get<uint32_t>("header");
  const uint64_t sum = h.get<uint64_t>("header");
  if (bytes.size() - kHeader < size)
    throw std::runtime_error(path + ": checkpoint is truncated (" + std::to_string(bytes.size()) + " of " +
                             std::to_string(kHeader + size) + " bytes)");
  if (bytes.size() - kHeader > size) throw std::runtime_error(path + ": checkpoint has trailing bytes");
  const std::string payload = bytes.substr(kHeader);
  if (io::fnv1a(payload) != sum) throw std::runtime_error(path + ": checkpoint is corrupt (checksum mismatch)");

  Reader r{payload, 0, path};
  Mlp net;
  MlpSpec& s = net.spec;
  s.inputs = int(r.get<uint32_t>("spec"));
  s.outputs = int(r.get<uint32_t>("spec"));
  const uint32_t hidden = r.get<uint32_t>("spec");
  if (hidden > uint32_t(kMaxHidden)) throw std::runtime_error(path + ": checkpoint has " + std::to_string(hidden) + " hidden layers");
  for (uint32_t i = 0; i < hidden; ++i) s.hidden.push_back(int(r.get<uint32_t>("spec")));
  std::string hidden_name, output_name;
  try {
    hidden_name = r.str("spec");
    s.slope = r.get<double>("spec");
    output_name = r.str("spec");
    s.color = shading::parse_color_space(r.str("spec"));
    s.activation = s.output_activation = Activation::tanh;  // resolved below, after the entries
    s.validate();  // widths before they size anything; again below with the entries' parameters
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(path + ": bad network spec in checkpoint: " + e.what());
  }
  const uint32_t names = r.get<uint32_t>("input names");
  for (uint32_t i = 0; i < names; ++i) net.input_names.push_back(r.str("input names"));
  net.trained_steps = r.get<uint64_t>("counters");
  // The count is checked against the spec once the sections (its encodings) are read; until
  // then it only has to fit in the file.
  const uint64_t count = r.get<uint64_t>("parameters");
  r.need(count > payload.size() / sizeof(float) ? payload.size() + 1 : std::size_t(count) * sizeof(float), "parameters");
  net.params.resize(count);
  for (auto& v : net.params) v = r.get<float>("parameters");
  // A valid checksum says the bytes are as written, not that the numbers are usable.
  if (std::string bad = first_nonfinite(s, net.params); !bad.empty())
    throw std::runtime_error(path + ": checkpoint refused: its " + bad);
  net.best_epoch = int(r.get<uint32_t>("best snapshot"));
  if (net.best_epoch > 0) {
    net.best_val_mse = r.get<double>("best snapshot");
    if (!(net.best_val_mse >= 0 && std::isfinite(net.best_val_mse)))
      throw std::runtime_error(path + ": checkpoint refused: its best validation MSE is " + io::number_text(net.best_val_mse));
    net.best_params.resize(count);
    for (auto& v : net.best_params) v = r.get<float>("best snapshot");
    if (std::string bad = first_nonfinite(s, net.best_params); !bad.empty())
      throw std::runtime_error(path + ": checkpoint refused: its best-epoch snapshot's " + bad);
  }
  std::map<std::string, std::string> defs;  // "NAME glsl" / "NAME grad" -> text
  std::map<std::string, std::string> encoding_defs;  // "NAME glsl" -> a user's encoding's text
  std::vector<std::string> encoding_kinds;  // per s.encodings entry
  while (r.pos != payload.size()) {
    const std::string tag = r.str("sections");
    if (tag == "conditions") {
      const uint32_t n = r.get<uint32_t>("conditions");
      if (n > net.input_names.size()) throw std::runtime_error(path + ": checkpoint has more conditions than inputs");
      for (uint32_t i = 0; i < n; ++i) {
        Condition c;
        c.name = r.str("conditions");
        c.min = r.get<double>("conditions"), c.max = r.get<double>("conditions"), c.value = r.get<double>("conditions");
        if (!(std::isfinite(c.min) && std::isfinite(c.max) && std::isfinite(c.value) && c.min <= c.max) ||
            std::find(net.input_names.begin(), net.input_names.end(), c.name) == net.input_names.end())
          throw std::runtime_error(path + ": checkpoint has a bad condition '" + c.name + "'");
        net.conditions.push_back(c);
      }
    } else if (tag == "encodings") {
      const uint32_t n = r.get<uint32_t>("encodings");
      if (n > uint32_t(s.inputs)) throw std::runtime_error(path + ": checkpoint has more encodings than inputs");
      for (uint32_t i = 0; i < n; ++i) {
        InputEncoding e;
        e.input = r.str("encodings");
        const uint32_t offset = r.get<uint32_t>("encodings"), width = r.get<uint32_t>("encodings");
        if (offset >= uint32_t(s.inputs) || width > uint32_t(s.inputs))
          throw std::runtime_error(path + ": checkpoint encodes columns past the network's " + std::to_string(s.inputs) +
                                   " inputs");
        e.offset = int(offset);
        e.width = int(width);
        const std::string kind = r.str("encodings");
        e.n = int(std::min<uint32_t>(r.get<uint32_t>("encodings"), 1u << 20));  // checked by validate()
        e.include_input = r.get<uint8_t>("encodings") != 0;
        e.lo = r.get<double>("encodings");
        e.hi = r.get<double>("encodings");
        encoding_kinds.push_back(kind);  // resolved after the entries, which may define it
        s.encodings.push_back(e);
      }
    } else if (tag == "entries") {
      const uint32_t entries = r.get<uint32_t>("entries");
      for (uint32_t i = 0; i < entries; ++i) {
        const std::string key = r.str("entries"), value = r.str("entries");
        char* end = nullptr;
        const double v = std::strtod(value.c_str(), &end);
        const bool number = !value.empty() && end && *end == 0;
        if (key == "omega" && number) s.omega = v;
        else if (key == "alpha" && number) s.alpha = v;
        else if (key.rfind("activation ", 0) == 0) defs[key.substr(11)] = value;
        else if (key.rfind("encoding ", 0) == 0) encoding_defs[key.substr(9)] = value;
        else throw std::runtime_error(path + ": checkpoint entry '" + key + "' = '" + value + "' is not one this build reads");
      }
    } else {
      throw std::runtime_error(path + ": checkpoint has unknown bytes after the network");
    }
  }
  if (r.pos != payload.size()) throw std::runtime_error(path + ": checkpoint has unread bytes after the network");
  // Encodings by name; a user's one must be defined, as the checkpoint recorded it.
  for (std::size_t k = 0; k < s.encodings.size(); ++k) {
    InputEncoding& e = s.encodings[k];
    const std::string& kind = encoding_kinds[k];
    const auto glsl = encoding_defs.find(kind + " glsl");
    const bool recorded = glsl != encoding_defs.end();
    if (!find_encoding(kind, &e.kind)) {
      if (recorded)
        throw std::runtime_error(path + ": the network encodes input '" + e.input + "' with '" + kind +
                                 "', which is not defined; define it before sn.load with sn.encoding.define{ name = \"" +
                                 kind + "\", glsl = \"" + glsl->second + "\", lua = ..., outputs = ... }");
      throw std::runtime_error(path + ": the network encodes input '" + e.input + "' with '" + kind +
                               "', which this build does not know (valid: " + io::join(encoding_names()) + ")");
    }
    if (recorded && encoding_def(e.kind).glsl != glsl->second)
      throw std::runtime_error(path + ": encoding '" + kind + "' is defined differently from the network's (glsl = \"" +
                               glsl->second + "\")");
  }
  try {
    s.validate();  // the encodings, before they size anything
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(path + ": bad network spec in checkpoint: " + e.what());
  }
  // Activations by name; a user's one must be defined, as the checkpoint recorded it.
  auto resolve = [&](const std::string& name, Position where, const char* option) {
    const auto glsl = defs.find(name + " glsl"), grad = defs.find(name + " grad");
    const bool recorded = glsl != defs.end() && grad != defs.end();
    Activation a;
    if (!find_activation(name, &a) && recorded)
      throw std::runtime_error(path + ": the network uses activation '" + name +
                               "', which is not defined; define it before sn.load with sn.activation.define{ name = \"" +
                               name + "\", glsl = \"" + glsl->second + "\", grad = \"" + grad->second +
                               "\", lua = ..., lua_grad = ... }");
    if (recorded && (activation_def(a).glsl != glsl->second || activation_def(a).grad != grad->second))
      throw std::runtime_error(path + ": activation '" + name + "' is defined differently from the network's (glsl = \"" +
                               glsl->second + "\", grad = \"" + grad->second + "\")");
    try {
      return parse_activation(name, where, option);
    } catch (const std::invalid_argument& e) {
      throw std::runtime_error(path + ": bad network spec in checkpoint: " + e.what());
    }
  };
  s.activation = resolve(hidden_name, Position::hidden, "activation");
  s.output_activation = resolve(output_name, Position::output, "output_activation");
  try {
    s.validate();
  } catch (const std::invalid_argument& e) {
    throw std::runtime_error(path + ": bad network spec in checkpoint: " + e.what());
  }
  if (count != s.param_count())  // with the spec complete: its description names the real activations
    throw std::runtime_error(path + ": checkpoint has " + std::to_string(count) + " parameters, its spec " +
                             s.describe() + " needs " + std::to_string(s.param_count()));
  if (std::string why = input_names_problem(net); !why.empty())
    throw std::runtime_error(path + ": checkpoint refused: its " + why);
  return net;
}

}  // namespace sn::nn
