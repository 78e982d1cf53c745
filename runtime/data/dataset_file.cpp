#include "data/dataset_file.h"

#include <unistd.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <nlohmann/json.hpp>

#include "data/input_layout.h"
#include "io/atomic_write.h"
#include "io/file_lock.h"
#include "io/hash.h"
#include "io/npy.h"
#include "io/read_file.h"
#include "scene/gbuffer.h"

namespace sn::data {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;  // keeps the sidecar's fields in the order written

namespace {

constexpr const char* kFormat = "shadenet-dataset";
constexpr int kVersion = 1;
constexpr uint64_t kMaxRows = uint64_t(1) << 31;  // as sn.dataset{...}: keeps every size product in range

// A NumPy export's files: the sidecar, and the arrays named after its stem.
DatasetPaths numpy_paths(const std::string& sidecar, const std::string& stem) {
  DatasetPaths d;
  d.main = sidecar;
  d.inputs = stem + ".inputs.npy";
  d.targets = stem + ".targets.npy";
  return d;
}

// A numbered column name: "y3". (Built with +=: GCC 12 warns falsely (-Wrestrict) on "y" + std::to_string(k).)
std::string numbered(char letter, std::size_t k) {
  std::string name(1, letter);
  name += std::to_string(k);
  return name;
}

// The sidecar a path names, links followed: its arrays lie beside it (an export through a link
// writes them there, the loader reads them there).
std::string real_sidecar(const std::string& main) { return io::through_links(main); }

// A hash of everything a trainer reads: equal rows, sets, widths, colour and names, equal key.
std::string content_key(const Dataset& d) {
  io::Fnv1a f;
  const int head[3] = {d.inputs, d.outputs, int(d.color)};
  f.bytes(head, sizeof head);
  uint64_t n = d.input_names.size();
  f.bytes(&n, sizeof n);
  for (const auto& s : d.input_names) {
    n = s.size();
    f.bytes(&n, sizeof n);
    f.text(s);
  }
  for (const auto& c : d.conditions) {
    f.text(c.name);
    f.bytes(&c.min, sizeof c.min);
    f.bytes(&c.max, sizeof c.max);
  }
  f.vec(d.train_x);
  f.vec(d.train_y);
  f.vec(d.val_x);
  f.vec(d.val_y);
  return "file-" + io::hex64(f.h);
}

std::string color_columns(shading::ColorSpace c, int outputs, std::vector<std::string>* names) {
  static const char* kCols[4][3] = {{"r", "g", "b"}, {"h", "s", "v"}, {"X", "Y", "Z"}, {"L", "a", "b"}};
  if (outputs == 3) {
    for (int k = 0; k < 3; ++k) names->push_back(kCols[int(c)][k]);
    return "";
  }
  if (c != shading::ColorSpace::rgb)
    return std::string("CSV names the colour space by its three target columns; ") + std::to_string(outputs) +
           " targets in " + shading::color_space_name(c) + " cannot be written (use .json: the NumPy sidecar keeps it)";
  for (int k = 1; k <= outputs; ++k) names->push_back(numbered('y', k));
  return "";
}

std::vector<std::string> csv_columns(const Dataset& d) {
  std::vector<std::string> cols;
  if (d.input_names.empty()) {
    for (int k = 1; k <= d.inputs; ++k) cols.push_back(numbered('x', k));
  } else {
    std::vector<InputSlot> layout;
    try {
      layout = input_layout(d);
    } catch (const std::exception& e) {
      throw std::invalid_argument(std::string("CSV column names cannot carry these inputs: ") + e.what() +
                                  " (use .json: the NumPy sidecar keeps any names)");
    }
    // The reader takes G-buffer attributes' columns only, and a column keeps no range.
    if (!d.conditions.empty())
      throw std::invalid_argument("CSV column names cannot carry the varied parameter '" + d.conditions[0].name +
                                  "' and its range (use .json: the NumPy sidecar keeps them)");
    for (const auto& s : layout)
      for (int c = 0; c < s.width; ++c) cols.push_back(s.name + "_" + component_letter(s.name, c));
  }
  std::string why = color_columns(d.color, d.outputs, &cols);
  if (!why.empty()) throw std::invalid_argument(why);
  cols.push_back("set");
  return cols;
}

// The shortest text that reads back as the same float32 ("0.1", "-0", "1e-45").
inline void put_float(std::string& out, float v) {
  char b[32];
  auto r = std::to_chars(b, b + sizeof b, v);
  out.append(b, r.ptr);
}

void write_csv(const Dataset& d, const std::string& path) {
  std::string text = csv_header(d) + "\n";
  text.reserve(text.size() + (d.train_count() + d.val_count()) * std::size_t(d.inputs + d.outputs + 1) * 12);
  for (int s = 0; s < 2; ++s) {
    const auto& X = s == 0 ? d.train_x : d.val_x;
    const auto& Y = s == 0 ? d.train_y : d.val_y;
    const std::size_t n = s == 0 ? d.train_count() : d.val_count();
    const char* set = s == 0 ? "train\n" : "val\n";
    for (std::size_t r = 0; r < n; ++r) {
      for (int k = 0; k < d.inputs; ++k) put_float(text, X[r * d.inputs + k]), text += ',';
      for (int k = 0; k < d.outputs; ++k) put_float(text, Y[r * d.outputs + k]), text += ',';
      text += set;
    }
  }
  io::write_file_atomic(path, text, "dataset");
}

// Rows of both sets, training first, as one array.
std::string npy_of(const std::vector<float>& train, const std::vector<float>& val, std::size_t rows, int width) {
  std::string out = io::npy_header(rows, std::size_t(width));
  out.append(reinterpret_cast<const char*>(train.data()), train.size() * sizeof(float));
  out.append(reinterpret_cast<const char*>(val.data()), val.size() * sizeof(float));
  return out;
}

// Where an export keeps an old array while it replaces it: ".NAME.previous" beside it.
std::string kept_name(const std::string& array) {
  const fs::path a(array);
  return (a.parent_path() / ("." + a.filename().string() + ".previous")).string();
}

// Removes the kept arrays once the new sidecar is in place (or a killed export's, once a later
// one's is).
void remove_kept(const DatasetPaths& p) {
  std::error_code ec;
  fs::remove(kept_name(p.inputs), ec);
  fs::remove(kept_name(p.targets), ec);
}

// Before an export renames its arrays over the old ones: the old arrays get a second name
// (a hard link, ".NAME.previous") and the old sidecar is rewritten to name them there, so until
// the new sidecar replaces it the old export loads whole, whatever is renamed meanwhile. An old
// sidecar that cannot be read has nothing to keep; where links cannot be made (a file system
// without them) the old sidecar stays as it is and a kill between the renames leaves it over
// new arrays, which loading refuses (content_key).
void keep_old_export(const DatasetPaths& p, const fs::path& folder) {
  Json old;
  try {
    if (!fs::is_regular_file(fs::symlink_status(p.main))) return;
    old = Json::parse(io::read_file(p.main, "dataset"));
  } catch (const std::exception&) {
    return;
  }
  if (!old.is_object()) return;
  std::vector<std::string> made;
  bool all = true;
  for (const char* group : {"inputs", "targets"}) {
    auto g = old.find(group);
    if (g == old.end() || !g->is_object() || !g->contains("file") || !(*g)["file"].is_string()) continue;
    const fs::path at = (folder / (*g)["file"].get<std::string>()).lexically_normal();
    const bool replaced = at == fs::path(p.inputs).lexically_normal() || at == fs::path(p.targets).lexically_normal();
    if (!replaced) continue;  // the new export leaves that file alone
    const std::string kept = kept_name(at.string());
    std::error_code ec;
    fs::remove(kept, ec);
    if (::link(at.c_str(), kept.c_str()) != 0) {
      all = all && errno == ENOENT;  // an array already missing: that export was broken before
      continue;
    }
    made.push_back(kept);
    (*g)["file"] = fs::path(kept).filename().string();
  }
  if (!all || made.empty()) {
    for (const auto& k : made) ::unlink(k.c_str());
    return;
  }
  try {
    io::write_file_atomic(p.main, old.dump(2) + "\n", "dataset");
  } catch (...) {  // (a full disk): the old sidecar stands as it was, over its arrays
    for (const auto& k : made) ::unlink(k.c_str());
    throw;
  }
}

// Returns the files written (through a link: where it leads).
DatasetPaths write_numpy(const Dataset& d, const DatasetPaths& given) {
  // Through a link, where it leads: the sidecar there, the arrays beside it and named after it,
  // the link kept. (The link was removed and the arrays landed beside it: nothing loaded.)
  const std::string real = real_sidecar(given.main);
  const DatasetPaths p =
      real == given.main ? given
                         : numpy_paths(real, fs::path(real).extension() == ".json" ? real.substr(0, real.size() - 5) : real);
  const std::size_t rows = d.train_count() + d.val_count();
  Json side;
  side["format"] = kFormat;
  side["version"] = kVersion;
  side["inputs"] = {{"file", fs::path(p.inputs).filename().string()}, {"width", d.inputs}, {"names", d.input_names}};
  side["targets"] = {{"file", fs::path(p.targets).filename().string()}, {"width", d.outputs},
                     {"color", shading::color_space_name(d.color)}};
  side["rows"] = {{"train", d.train_count()}, {"val", d.val_count()}};
  if (!d.conditions.empty()) {
    Json c = Json::array();
    for (const auto& r : d.conditions) c.push_back({{"name", r.name}, {"min", r.min}, {"max", r.max}});
    side["inputs"]["conditions"] = c;
  }
  side["source_key"] = d.key;
  // The rows' own key, checked on loading: arrays from another export (one killed part-way,
  // files copied together by hand) are refused, never trained on as a mix.
  side["content_key"] = content_key(d);
  const std::string sidecar = side.dump(2) + "\n";

  std::error_code ec;
  const auto st = fs::status(p.main, ec);
  // A sidecar names arrays beside it: it is a file in a folder, not a device or a stream.
  if (fs::exists(st) && !fs::is_regular_file(st))
    throw std::runtime_error("cannot write dataset '" + p.main + "': " +
                             (fs::is_directory(st) ? "it is a directory" : "not a regular file"));
  // One export at a time in a folder, and no load meanwhile (each waits for the other): two
  // exports to one path interleaved their renames, and a reader took one's inputs with the
  // other's targets.
  const fs::path folder = fs::path(p.main).has_parent_path() ? fs::path(p.main).parent_path() : fs::path(".");
  fs::create_directories(folder, ec);  // (a failure is the writing's to report)
  const io::FileLock lock = io::FileLock::acquire(folder.string(), io::FileLock::Mode::exclusive);
  // What a killed export of these files left: its temporaries (under the lock nobody writes
  // them now; without one, only those a minute old) and the old arrays it kept.
  const std::vector<std::string> names = {fs::path(p.inputs).filename().string(),
                                          fs::path(p.targets).filename().string(), fs::path(p.main).filename().string()};
  io::remove_stale_temporaries(folder.string(), lock.held() ? 0 : 60, names);
  // All three are written before any replaces its old file: a failure there (a full disk) leaves
  // the old export whole. Then the old export is kept under other names (keep_old_export) while
  // the arrays are renamed and the sidecar last, so a kill or a failed rename at any moment
  // leaves a sidecar whose arrays are its own: the old export, or the new one.
  io::write_files_atomic({{p.inputs, npy_of(d.train_x, d.val_x, rows, d.inputs)},
                          {p.targets, npy_of(d.train_y, d.val_y, rows, d.outputs)},
                          {p.main, sidecar}},
                         "dataset", [&] { keep_old_export(p, folder); });
  remove_kept(p);
  return p;
}

// ---- loading ----

void check_finite(const std::vector<float>& v, int width, const std::string& where, std::size_t first_row = 0) {
  for (std::size_t i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]))
      throw std::runtime_error(where + ": row " + std::to_string(first_row + i / width + 1) + " column " +
                               std::to_string(i % width + 1) + " is " + (std::isnan(v[i]) ? "NaN" : "infinite"));
}

// Fields of the sidecar, each error naming the file and the field.
struct Sidecar {
  const Json& root;
  const std::string& path;

  [[noreturn]] void fail(const std::string& why) const { throw std::runtime_error(path + ": " + why); }
  const Json* find(const char* group, const char* key) const {
    const Json* j = &root;
    if (group) {
      auto g = root.find(group);
      if (g == root.end()) return nullptr;
      if (!g->is_object()) fail(std::string("field '") + group + "' must be an object, got " + g->dump());
      j = &*g;
    }
    auto it = j->find(key);
    return it == j->end() ? nullptr : &*it;
  }
  static std::string name(const char* group, const char* key) { return group ? std::string(group) + "." + key : key; }
  const Json& need(const char* group, const char* key) const {
    const Json* j = find(group, key);
    if (!j) fail("missing field '" + name(group, key) + "'");
    return *j;
  }
  std::string text(const char* group, const char* key, const char* def = nullptr) const {
    const Json* j = find(group, key);
    if (!j && def) return def;
    if (!j) need(group, key);
    if (!j->is_string()) fail("field '" + name(group, key) + "' must be a string, got " + j->dump());
    return j->get<std::string>();
  }
  uint64_t count(const char* group, const char* key, uint64_t min) const {
    const Json& j = need(group, key);
    if (!j.is_number_unsigned() || j.get<uint64_t>() < min)  // JSON reads non-negative integers as unsigned
      fail("field '" + name(group, key) + "' must be an integer of at least " + std::to_string(min) + ", got " + j.dump());
    return j.get<uint64_t>();
  }
};

std::shared_ptr<Dataset> load_numpy(const DatasetPaths& p) {
  // No export replaces the files while they are read (write_numpy).
  const fs::path real = real_sidecar(p.main);
  const io::FileLock lock =
      io::FileLock::acquire(real.has_parent_path() ? real.parent_path().string() : ".", io::FileLock::Mode::shared);
  const std::string text = io::read_file(p.main, "dataset");
  Json root;
  try {
    root = Json::parse(text);
  } catch (const Json::exception& e) {
    throw std::runtime_error(p.main + ": malformed JSON: " + e.what());
  }
  if (!root.is_object()) throw std::runtime_error(p.main + ": not a dataset sidecar (a JSON object expected)");
  const Sidecar s{root, p.main};
  const std::string format = s.text(nullptr, "format");
  if (format != kFormat) s.fail("not a shadenet dataset sidecar (format '" + format + "', expected '" + kFormat + "')");
  const uint64_t version = s.count(nullptr, "version", 1);
  if (version != uint64_t(kVersion))
    s.fail("dataset file version " + std::to_string(version) + "; this build reads version " + std::to_string(kVersion));

  auto d = std::make_shared<Dataset>();
  const uint64_t in_w = s.count("inputs", "width", 1), out_w = s.count("targets", "width", 1);
  if (in_w > 1u << 20 || out_w > 1u << 20) s.fail("input or target width above 2^20");
  d->inputs = int(in_w);
  d->outputs = int(out_w);
  const std::string color = s.text("targets", "color", "rgb");
  try {
    d->color = shading::parse_color_space(color);
  } catch (const std::exception& e) {
    s.fail(std::string("field 'targets.color': ") + e.what());
  }
  if (const Json* names = s.find("inputs", "names")) {
    if (!names->is_array()) s.fail("field 'inputs.names' must be an array of strings, got " + names->dump());
    for (const auto& n : *names) {
      if (!n.is_string()) s.fail("field 'inputs.names' must be an array of strings, got " + names->dump());
      d->input_names.push_back(n.get<std::string>());
    }
  }
  if (const Json* conds = s.find("inputs", "conditions")) {
    auto bad = [&] { s.fail("field 'inputs.conditions' must be an array of {name, min, max}, got " + conds->dump()); };
    if (!conds->is_array()) bad();
    for (const auto& c : *conds) {
      if (!c.is_object() || !c.contains("name") || !c["name"].is_string() || !c.contains("min") ||
          !c["min"].is_number() || !c.contains("max") || !c["max"].is_number())
        bad();
      d->conditions.push_back({c["name"].get<std::string>(), c["min"].get<double>(), c["max"].get<double>()});
    }
  }
  try {
    input_layout(*d);
  } catch (const std::exception& e) {
    s.fail(std::string("field 'inputs': ") + e.what());
  }
  const uint64_t train = s.count("rows", "train", 1), val = s.count("rows", "val", 0);
  if (train > kMaxRows || val > kMaxRows) s.fail("more than 2^31 rows in a set");
  s.text(nullptr, "source_key", "");  // provenance for people; the loaded key is the content's

  const fs::path folder = real.parent_path();
  auto array = [&](const char* group, uint64_t width) {
    const std::string file = s.text(group, "file");
    if (file.empty()) s.fail(std::string("field '") + group + ".file' is empty");
    const std::string at = (folder / file).string();
    io::NpyArray a = io::parse_npy(io::read_file(at, "dataset array"), at);
    if (a.rows != train + val || a.cols != width)
      throw std::runtime_error(at + ": shape (" + std::to_string(a.rows) + ", " + std::to_string(a.cols) +
                               ") does not match the sidecar " + p.main + ": (" + std::to_string(train + val) + ", " +
                               std::to_string(width) + ") (rows.train + rows.val, " + group + ".width)");
    check_finite(a.data, int(width), at);
    return a;
  };
  io::NpyArray x = array("inputs", in_w);
  io::NpyArray y = array("targets", out_w);
  d->train_x.assign(x.data.begin(), x.data.begin() + train * in_w);
  d->val_x.assign(x.data.begin() + train * in_w, x.data.end());
  d->train_y.assign(y.data.begin(), y.data.begin() + train * out_w);
  d->val_y.assign(y.data.begin() + train * out_w, y.data.end());
  d->key = content_key(*d);
  const std::string exported = s.text(nullptr, "content_key", "");  // absent: written before it was, or elsewhere
  if (!exported.empty() && exported != d->key)
    s.fail("its arrays " + fs::path(s.text("inputs", "file")).filename().string() + " and " +
           fs::path(s.text("targets", "file")).filename().string() +
           " do not hold the rows it was exported with (content_key " + exported + "; the arrays give " + d->key +
           "): they come from another export (one killed part-way, or files copied together); export the dataset "
           "again (if the arrays were changed on purpose, remove content_key from the sidecar)");
  return d;
}

// The colour space and width the target columns (those before "set") name, read from the end.
struct TargetColumns {
  shading::ColorSpace color = shading::ColorSpace::rgb;
  int width = 0;
};
TargetColumns target_columns(const std::vector<std::string>& cols, std::size_t end) {
  static const char* kCols[4][3] = {{"r", "g", "b"}, {"h", "s", "v"}, {"X", "Y", "Z"}, {"L", "a", "b"}};
  if (end >= 3)
    for (int c = 0; c < 4; ++c)
      if (cols[end - 3] == kCols[c][0] && cols[end - 2] == kCols[c][1] && cols[end - 1] == kCols[c][2])
        return {shading::ColorSpace(c), 3};
  // y1..ym: the longest run of y<k> at the end, which must count up from y1.
  std::size_t first = end;
  while (first > 0 && cols[first - 1].size() > 1 && cols[first - 1][0] == 'y' &&
         cols[first - 1].find_first_not_of("0123456789", 1) == std::string::npos)
    --first;
  for (std::size_t i = first; i < end; ++i)
    if (cols[i] != numbered('y', i - first + 1)) return {};
  return {shading::ColorSpace::rgb, int(end - first)};
}

// Input names from columns "normal_x,normal_y,normal_z,uv_u,uv_v" (or none from "x1..xn").
std::vector<std::string> input_names_of(const std::vector<std::string>& cols, std::size_t n, const std::string& where) {
  bool plain = true;
  for (std::size_t i = 0; i < n; ++i) plain = plain && cols[i] == numbered('x', i + 1);
  if (plain) return {};
  std::vector<std::string> names;
  for (std::size_t i = 0; i < n;) {
    const std::size_t cut = cols[i].rfind('_');
    const std::string name = cut == std::string::npos ? "" : cols[i].substr(0, cut);
    const auto& valid = scene::gbuffer_attribute_names();
    bool known = false;
    for (const auto& v : valid) known = known || v == name;
    if (!known)
      throw std::runtime_error(where + ": input column '" + cols[i] + "' is not <attribute>_<component> (attributes: " +
                               name_list(valid) + "; e.g. normal_x, uv_u) and the inputs are not x1..x" +
                               std::to_string(n));
    const int w = scene::attribute_width(name);
    for (int c = 0; c < w; ++c) {
      const std::string want = name + "_" + component_letter(name, c);
      if (i + c >= n || cols[i + c] != want)
        throw std::runtime_error(where + ": input '" + name + "' needs the columns " + name + "_" + component_letter(name, 0) +
                                 ".." + name + "_" + component_letter(name, w - 1) + " in order; column " +
                                 std::to_string(i + c + 1) + " is '" + (i + c < n ? cols[i + c] : cols[n]) + "', expected '" +
                                 want + "'");
    }
    names.push_back(name);
    i += std::size_t(w);
  }
  return names;
}

std::shared_ptr<Dataset> load_csv(const std::string& path) {
  const std::string text = io::read_file(path, "dataset");
  // A UTF-8 byte order mark (Excel writes one) is not part of the first column's name.
  std::size_t at = text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? 3 : 0, line_no = 0;
  std::vector<std::string_view> fields;
  // The next non-blank line split at commas, fields trimmed; false at the end of the file.
  auto next_line = [&]() {
    while (at < text.size()) {
      std::size_t end = text.find('\n', at);
      if (end == std::string::npos) end = text.size();
      std::string_view line(text.data() + at, end - at);
      at = end + 1;
      ++line_no;
      if (line.find_first_not_of(" \t\r") == std::string_view::npos) continue;
      fields.clear();
      for (std::size_t s = 0;;) {
        std::size_t c = line.find(',', s);
        std::string_view f = line.substr(s, c == std::string_view::npos ? std::string_view::npos : c - s);
        while (!f.empty() && (f.front() == ' ' || f.front() == '\t')) f.remove_prefix(1);
        while (!f.empty() && (f.back() == ' ' || f.back() == '\t' || f.back() == '\r')) f.remove_suffix(1);
        fields.push_back(f);
        if (c == std::string_view::npos) break;
        s = c + 1;
      }
      return true;
    }
    return false;
  };
  const std::string file = path;
  auto where = [&]() { return file + ":" + std::to_string(line_no); };

  if (!next_line()) throw std::runtime_error(path + ": empty file (a header line expected)");
  std::vector<std::string> cols(fields.begin(), fields.end());
  const bool has_set = cols.back() == "set";
  const std::size_t end = cols.size() - (has_set ? 1 : 0);
  const TargetColumns t = target_columns(cols, end);
  if (t.width == 0)
    throw std::runtime_error(where() + ": cannot tell the target columns: the header must end in r,g,b / h,s,v / "
                                       "X,Y,Z / L,a,b / y1..ym, then set");
  if (end <= std::size_t(t.width)) throw std::runtime_error(where() + ": no input columns before the targets");
  auto d = std::make_shared<Dataset>();
  d->inputs = int(end - t.width);
  d->outputs = t.width;
  d->color = t.color;
  d->input_names = input_names_of(cols, end - t.width, where());

  const std::size_t ncols = cols.size();
  std::vector<float> row(end);
  while (next_line()) {
    if (fields.size() != ncols)
      throw std::runtime_error(where() + ": " + std::to_string(fields.size()) + " columns, the header has " +
                               std::to_string(ncols));
    for (std::size_t k = 0; k < end; ++k) {
      std::string_view f = fields[k];
      if (!f.empty() && f.front() == '+') f.remove_prefix(1);
      float v = 0;
      auto r = std::from_chars(f.data(), f.data() + f.size(), v);
      if (f.empty() || r.ptr != f.data() + f.size() || r.ec == std::errc::invalid_argument)
        throw std::runtime_error(where() + ": column '" + cols[k] + "': '" + std::string(fields[k]) + "' is not a number");
      if (r.ec == std::errc::result_out_of_range) {
        // Below float's smallest value it rounds to 0 (or a denormal), as a cast would; above its
        // largest it is an error.
        double wide = 0;
        std::from_chars(f.data(), f.data() + f.size(), wide);
        if (!(std::fabs(wide) < 1.0))
          throw std::runtime_error(where() + ": column '" + cols[k] + "': " + std::string(fields[k]) +
                                   " is outside float32's range");
        v = float(wide);
      }
      if (!std::isfinite(v))
        throw std::runtime_error(where() + ": column '" + cols[k] + "' is " + (std::isnan(v) ? "NaN" : "infinite"));
      row[k] = v;
    }
    bool train = true;
    if (has_set) {
      if (fields[end] == "val") train = false;
      else if (fields[end] != "train")
        throw std::runtime_error(where() + ": set '" + std::string(fields[end]) + "' is neither train nor val");
    }
    auto& X = train ? d->train_x : d->val_x;
    auto& Y = train ? d->train_y : d->val_y;
    X.insert(X.end(), row.begin(), row.begin() + d->inputs);
    Y.insert(Y.end(), row.begin() + d->inputs, row.end());
  }
  if (d->train_x.empty())
    throw std::runtime_error(path + ": no training rows" + (d->val_x.empty() ? " (no data lines)" : " (every row is set = val)"));
  d->key = content_key(*d);
  return d;
}

}  // namespace

DatasetPaths dataset_paths(const std::string& path) {
  const fs::path p(path);
  const std::string file = p.filename().string();
  if (file.empty() || file == "." || file == "..")
    throw std::invalid_argument("'" + path + "' names no file (expected e.g. out/cloth.json, out/cloth.csv or out/cloth)");
  const std::string ext = p.extension().string();
  if (ext == ".csv") {
    DatasetPaths d;
    d.format = DatasetFormat::csv;
    d.main = path;
    return d;
  }
  if (ext == ".json") return numpy_paths(path, path.substr(0, path.size() - ext.size()));
  if (ext.empty()) return numpy_paths(path + ".json", path);
  throw std::invalid_argument("'" + path + "': unknown dataset file type '" + ext +
                              "' (.json: NumPy arrays with a JSON sidecar; .csv; no extension: .json)");
}

std::string csv_header(const Dataset& d) {
  std::string line;
  for (const auto& c : csv_columns(d)) line += (line.empty() ? "" : ",") + c;
  return line;
}

DatasetPaths export_dataset(const Dataset& d, const std::string& path) {
  DatasetPaths p = dataset_paths(path);
  if (p.format == DatasetFormat::csv) {
    write_csv(d, p.main);
    return p;
  }
  const DatasetPaths written = write_numpy(d, p);
  p.inputs = written.inputs;  // beside the sidecar a link at p.main leads to; p.main loads it
  p.targets = written.targets;
  return p;
}

std::shared_ptr<Dataset> load_dataset(const std::string& path) {
  const DatasetPaths p = dataset_paths(path);
  return p.format == DatasetFormat::csv ? load_csv(p.main) : load_numpy(p);
}

}  // namespace sn::data
