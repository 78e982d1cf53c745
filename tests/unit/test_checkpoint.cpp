// Checkpoints: a round trip keeps everything bit for bit; damaged files are clear errors; a
// failed save leaves nothing behind.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <cmath>
#include <cstring>
#include <iterator>


#include "io/hash.h"
#include "nn/checkpoint.h"
#include "nn/oracle.h"
#include "io/temp_dir.h"

namespace sn::nn {
namespace {

namespace fs = std::filesystem;

// One scratch folder per test process, removed when the process ends.
fs::path scratch(const std::string& name) {
  static const sn::io::TempDir dir("test_checkpoint");
  return fs::path(dir.path()) / name;
}

Mlp sample_net() {
  MlpSpec s;
  s.inputs = 6;
  s.hidden = {13, 13, 6};
  s.outputs = 3;
  s.activation = Activation::leaky_relu;
  s.slope = 0.2;
  s.output_activation = Activation::sigmoid;
  s.color = shading::ColorSpace::hsv;
  Mlp net(s, Init::he, 7);
  net.input_names = {"normal", "view"};
  net.trained_steps = 123456789012ull;
  net.best_params = net.params;
  net.best_params[3] = -1.5f;
  net.best_val_mse = 0.000134;
  net.best_epoch = 17;
  return net;
}

std::string read_all(const fs::path& p) {
  std::ifstream f(p, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
}
void write_all(const fs::path& p, const std::string& s) {
  std::ofstream f(p, std::ios::binary | std::ios::trunc);
  f.write(s.data(), std::streamsize(s.size()));
}

// A checkpoint's bytes edited in place, their checksum (the header's last 8 bytes, over the
// payload after it) made good again: what a file damaged with care looks like.
void reseal(std::string& bytes) {
  const uint64_t sum = io::fnv1a(bytes.substr(24));
  std::memcpy(bytes.data() + 16, &sum, 8);
}

std::string load_error(const fs::path& p) {
  try {
    load_checkpoint(p.string());
  } catch (const std::exception& e) {
    return e.what();
  }
  return "(loaded)";
}

TEST(Checkpoint, RoundTripKeepsEverything) {
  Mlp net = sample_net();
  auto path = scratch("nested/dir/net.snmlp");  // parent folders are created
  save_checkpoint(net, path.string());
  Mlp back = load_checkpoint(path.string());
  EXPECT_EQ(back.spec.describe(), net.spec.describe());
  EXPECT_TRUE(back.spec.same_shape(net.spec));
  EXPECT_EQ(back.spec.color, shading::ColorSpace::hsv);
  EXPECT_EQ(back.params, net.params);
  EXPECT_EQ(back.best_params, net.best_params);
  EXPECT_EQ(back.best_val_mse, net.best_val_mse);
  EXPECT_EQ(back.best_epoch, 17);
  EXPECT_EQ(back.input_names, net.input_names);
  EXPECT_EQ(back.trained_steps, net.trained_steps);
  // Header: magic, version, payload size = file size - 24.
  std::string bytes = read_all(path);
  EXPECT_EQ(bytes.substr(0, 5), "snmlp");
  EXPECT_EQ(uint8_t(bytes[8]), kCheckpointVersion);
  uint32_t size;
  std::memcpy(&size, bytes.data() + 12, 4);
  EXPECT_EQ(size + 24u, bytes.size());
  // No temporary file is left beside it.
  int files = 0;
  for (auto& e : fs::directory_iterator(path.parent_path())) files += e.is_regular_file();
  EXPECT_EQ(files, 1);
}

TEST(Checkpoint, DamagedFilesAreClearErrors) {
  auto path = scratch("damaged.snmlp");
  save_checkpoint(sample_net(), path.string());
  const std::string good = read_all(path);
  auto bad = scratch("bad.snmlp");

  write_all(bad, good.substr(0, good.size() - 10));
  EXPECT_NE(load_error(bad).find("truncated"), std::string::npos) << load_error(bad);
  write_all(bad, good.substr(0, 10));
  EXPECT_NE(load_error(bad).find("bad magic"), std::string::npos) << load_error(bad);

  std::string flipped = good;
  flipped[good.size() / 2] ^= 0x10;
  write_all(bad, flipped);
  EXPECT_NE(load_error(bad).find("corrupt (checksum mismatch)"), std::string::npos) << load_error(bad);

  std::string newer = good;
  newer[8] = 2;
  write_all(bad, newer);
  EXPECT_NE(load_error(bad).find("format version 2, this build reads 1"), std::string::npos) << load_error(bad);

  write_all(bad, "hello, not a network");
  EXPECT_NE(load_error(bad).find("not a shadenet network checkpoint"), std::string::npos);
  EXPECT_NE(load_error(scratch("missing.snmlp")).find("cannot read checkpoint"), std::string::npos);
  EXPECT_EQ(load_error(path), "(loaded)");
}

// A checkpoint with a NaN or infinite parameter is refused when saved (nothing is written, an old
// file stays) and when loaded, even with a valid checksum; the error names the file and where
// the first bad parameter lives. A non-regular file is not read at all.
TEST(Checkpoint, NonFiniteParametersAreRefusedOnSaveAndLoad) {
  Mlp net = sample_net();
  const auto path = scratch("finite.snmlp");
  save_checkpoint(net, path.string());
  const std::string good = read_all(path);
  // Layer 2's weight row 4, column 3: flat index weight_offset(1) + 3 * 13 + 2.
  const std::size_t j = net.spec.weight_offset(1) + 3 * 13 + 2;
  EXPECT_EQ(net.spec.param_name(j), "layer 2 weight[4][3]");
  EXPECT_EQ(net.spec.param_name(net.spec.bias_offset(0) + 1), "layer 1 bias[2]");
  Mlp bad = net;
  bad.params[j] = std::nanf("");
  try {
    save_checkpoint(bad, path.string());
    ADD_FAILURE() << "saved a NaN";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("layer 2 weight[4][3] (parameter " + std::to_string(j + 1) + " of"),
              std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("is NaN"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read_all(path), good);  // the old checkpoint is untouched
  bad = net;
  bad.best_params[5] = INFINITY;
  EXPECT_THROW(save_checkpoint(bad, path.string()), std::runtime_error);

  // The same bytes with the parameter patched to +inf and the checksum made valid again.
  auto patched = [&](std::size_t index, float value, bool best) {
    Mlp marked = net;
    const float mark = 1234.5678f;
    (best ? marked.best_params : marked.params)[index] = mark;
    if (!best) marked.best_params[index] = net.best_params[index];
    save_checkpoint(marked, path.string());
    std::string bytes = read_all(path);
    char m[4], v[4];
    std::memcpy(m, &mark, 4);
    std::memcpy(v, &value, 4);
    const std::size_t at = bytes.find(std::string(m, 4));
    EXPECT_NE(at, std::string::npos);
    bytes.replace(at, 4, std::string(v, 4));
    reseal(bytes);
    const auto out = scratch("nonfinite.snmlp");
    write_all(out, bytes);
    return out.string();
  };
  std::string file = patched(j, INFINITY, false);
  std::string err = load_error(file);
  EXPECT_NE(err.find(file), std::string::npos) << err;
  EXPECT_NE(err.find("layer 2 weight[4][3]"), std::string::npos) << err;
  EXPECT_NE(err.find("is infinite"), std::string::npos) << err;
  file = patched(2, std::nanf(""), true);
  err = load_error(file);
  EXPECT_NE(err.find("best-epoch snapshot's layer 1 weight[1][3] (parameter 3 of"), std::string::npos) << err;
  EXPECT_NE(load_error("/dev/zero").find("not a regular file"), std::string::npos) << load_error("/dev/zero");
}

// A checkpoint written before the activation registry (tests/data/checkpoint_v1.snmlp, saved by
// `net:save` at ccace90) loads, and computes what it computed then.
TEST(Checkpoint, VersionOneFilesStillLoad) {
  Mlp net = load_checkpoint(std::string(SHADENET_TEST_DIR) + "/data/checkpoint_v1.snmlp");
  EXPECT_EQ(net.spec.describe(), "mlp(3 -> 5 -> 4 -> 2, leaky_relu 0.2, out sigmoid)");
  EXPECT_EQ(net.input_names, std::vector<std::string>{"normal"});
  const std::string bytes = read_all(std::string(SHADENET_TEST_DIR) + "/data/checkpoint_v1.snmlp");
  EXPECT_EQ(uint8_t(bytes[8]), 1);
  // Outputs for (0.3, -0.7, 0.5), printed by that build: 0.50289911 0.578237057.
  std::vector<double> p(net.params.begin(), net.params.end());
  const double x[3] = {0.3f, -0.7f, 0.5f};
  auto y = oracle::forward(net.spec, p, x);
  EXPECT_NEAR(y[0], 0.50289911, 1e-6);
  EXPECT_NEAR(y[1], 0.578237057, 1e-6);
}

// The activations' parameters other than leaky_relu's slope travel in the "entries" section.
TEST(Checkpoint, ActivationParametersRoundTrip) {
  MlpSpec s;
  s.inputs = 3;
  s.hidden = {4};
  s.outputs = 2;
  s.activation = Activation::sine;
  s.omega = 30;
  s.output_activation = Activation::elu;
  s.alpha = 0.35;
  Mlp net(s, Init::siren, 2);
  auto path = scratch("sine.snmlp");
  save_checkpoint(net, path.string());
  Mlp back = load_checkpoint(path.string());
  EXPECT_EQ(back.spec.omega, 30);
  EXPECT_EQ(back.spec.alpha, 0.35);
  EXPECT_EQ(back.spec.describe(), "mlp(3 -> 4 -> 2, sine 30, out elu 0.35)");
  EXPECT_TRUE(back.spec.same_shape(net.spec));
  EXPECT_EQ(back.params, net.params);
}

// Input encodings travel in the "encodings" section; a network that uses none writes none (the
// file an older build reads), and an encoding this build does not know is a clear error.
TEST(Checkpoint, EncodingsRoundTrip) {
  MlpSpec s;
  s.inputs = 9;  // normal, view, uv, roughness
  s.hidden = {10, 7};
  s.outputs = 3;
  InputEncoding sh = default_encoding(Encoding::sh, "normal", 0, 3);
  sh.n = 3;
  InputEncoding tri = default_encoding(Encoding::triangle_wave, "uv", 6, 2);
  tri.include_input = true;
  InputEncoding blob = default_encoding(Encoding::oneblob, "roughness", 8, 1);
  blob.n = 12, blob.lo = 0.05, blob.hi = 1.0;
  s.encodings = {sh, tri, blob};
  Mlp net(s, Init::xavier, 3);
  net.input_names = {"normal", "view", "uv", "roughness"};
  net.best_params = net.params;
  net.best_epoch = 2;
  auto path = scratch("encoded.snmlp");
  save_checkpoint(net, path.string());
  Mlp back = load_checkpoint(path.string());
  EXPECT_EQ(back.spec.describe(),
            "mlp(9 -> 10 -> 7 -> 3, tanh; normal: sh 3, uv: triangle_wave 6 + input, roughness: oneblob 12 on [0.05, 1] "
            "-> 38 inputs)");
  EXPECT_EQ(back.spec.encodings, net.spec.encodings);
  EXPECT_TRUE(back.spec.same_shape(net.spec));
  EXPECT_EQ(back.params, net.params);
  EXPECT_EQ(back.best_params, net.best_params);
  std::vector<double> p(net.params.begin(), net.params.end());
  const double x[9] = {0, 0.6, 0.8, 1, 0, 0, 0.25, 0.5, 0.3};
  EXPECT_EQ(oracle::forward(back.spec, p, x), oracle::forward(net.spec, p, x));

  const std::string good = read_all(path);
  EXPECT_NE(good.find("encodings"), std::string::npos);
  save_checkpoint(sample_net(), scratch("plain.snmlp").string());
  EXPECT_EQ(read_all(scratch("plain.snmlp")).find("encodings"), std::string::npos);
  // The payload renamed to an unknown encoding (same length), its checksum made good again.
  std::string renamed = good;
  const std::size_t at = renamed.find("triangle_wave");
  ASSERT_NE(at, std::string::npos);
  renamed.replace(at, 13, "triangle_wavy");
  reseal(renamed);
  auto bad = scratch("unknown_encoding.snmlp");
  write_all(bad, renamed);
  EXPECT_NE(load_error(bad).find("the network encodes input 'uv' with 'triangle_wavy', which this build does not know "
                                 "(valid: identity, frequency, oneblob, sh, triangle_wave)"),
            std::string::npos)
      << load_error(bad);
}

TEST(Checkpoint, FailedSaveLeavesTheOldFile) {
  auto dir = scratch("readonly");
  fs::create_directories(dir);
  auto path = dir / "net.snmlp";
  Mlp net = sample_net();
  save_checkpoint(net, path.string());
  const std::string before = read_all(path);
  // Saving onto a path whose parent is a file fails; nothing is created.
  auto blocked = path / "inner.snmlp";
  try {
    save_checkpoint(net, blocked.string());
    ADD_FAILURE() << "saved below a file";
  } catch (const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write checkpoint '" + blocked.string() + "': cannot create folder"), std::string::npos)
        << e.what();
  }
  EXPECT_FALSE(fs::exists(blocked));
  EXPECT_EQ(read_all(path), before);
  // Renaming onto a folder fails after the data was written: the temporary file goes away.
  auto folder = dir / "folder.snmlp";
  fs::create_directories(folder / "inside");
  EXPECT_THROW(save_checkpoint(net, folder.string()), std::exception);
  int entries = 0;
  for (auto& e : fs::directory_iterator(dir)) {
    ++entries;
    EXPECT_EQ(e.path().string().find(".tmp"), std::string::npos) << e.path();
  }
  EXPECT_EQ(entries, 2);  // net.snmlp and folder.snmlp
  // A later save replaces the file whole.
  net.params[0] = 42.0f;
  save_checkpoint(net, path.string());
  EXPECT_EQ(load_checkpoint(path.string()).params[0], 42.0f);
}


// A checkpoint whose input names or conditions cannot be what the network reads is refused at
// load, as non-finite numbers are (a valid checksum says only that the bytes are as written):
// names whose widths miss the inputs, a condition twice, one named like a G-buffer attribute,
// one whose value lies outside its range, a best MSE that is not a number.
TEST(Checkpoint, InconsistentNamesAndConditionsAreRefused) {
  MlpSpec s;
  s.inputs = 7;
  s.hidden = {4};
  s.outputs = 3;
  const Mlp good = [&] {
    Mlp n(s, Init::xavier, 1);
    n.input_names = {"normal", "view", "roughness"};
    n.conditions = {{"roughness", 0.1, 0.8, 0.3}};
    return n;
  }();
  const auto path = scratch("conditions.snmlp");
  save_checkpoint(good, path.string());
  EXPECT_EQ(load_checkpoint(path.string()).conditions[0].value, 0.3);
  const auto refused = [&](const std::function<void(Mlp&)>& edit, const std::string& why) {
    Mlp bad = good;
    edit(bad);
    save_checkpoint(bad, path.string());
    const std::string err = load_error(path);
    EXPECT_NE(err.find(path.string() + ": checkpoint refused: its " + why), std::string::npos) << err;
  };
  refused([](Mlp& n) { n.input_names = {"normal", "view", "uv"}; n.conditions.clear(); },
          "input names {normal, view, uv} describe 8 input columns, the network takes 7");
  refused([](Mlp& n) { n.input_names = {"normal", "normal", "roughness"}; }, "input 'normal' is listed twice");
  refused([](Mlp& n) { n.conditions[0].value = 5; },
          "condition 'roughness' = 5 lies outside the range the network was trained on, [0.1, 0.8]");
  refused([](Mlp& n) { n.conditions[0].value = 0.8000001; }, "condition 'roughness' = 0.8000001 lies outside");
  refused([](Mlp& n) { n.conditions.push_back(n.conditions[0]); }, "condition 'roughness' is listed twice");
  refused([](Mlp& n) { n.conditions.push_back({"normal", 0, 1, 0.5}); }, "condition 'normal' is a G-buffer attribute");
  refused([](Mlp& n) { n.best_params = n.params, n.best_epoch = 2, n.best_val_mse = -5; }, "best validation MSE is -5");
}

// The parameter count's error describes the network the file holds, its activations included
// (they were a placeholder's, tanh, when the count was checked).
TEST(Checkpoint, ParameterCountErrorNamesTheRealNetwork) {
  MlpSpec s;
  s.inputs = 6;
  s.hidden = {4};
  s.outputs = 3;
  s.activation = Activation::relu;
  Mlp net(s, Init::he, 1);
  const auto path = scratch("count.snmlp");
  save_checkpoint(net, path.string());
  std::string bytes = read_all(path);
  // The count (a uint64) stands just before the parameters: one fewer, and the last one dropped.
  uint64_t count = net.params.size();
  std::string first(8 + 4, '\0');
  std::memcpy(first.data(), &count, 8);
  std::memcpy(first.data() + 8, net.params.data(), 4);
  const std::size_t at = bytes.find(first);
  ASSERT_NE(at, std::string::npos);
  --count;
  std::memcpy(bytes.data() + at, &count, 8);
  bytes.erase(at + 8 + 4 * count, 4);
  uint32_t size;  // the header's payload size, after the magic and the version
  std::memcpy(&size, bytes.data() + 12, 4);
  size -= 4;
  std::memcpy(bytes.data() + 12, &size, 4);
  reseal(bytes);
  write_all(path, bytes);
  const std::string err = load_error(path);
  EXPECT_NE(err.find("checkpoint has 42 parameters, its spec " + s.describe() + " needs 43"), std::string::npos) << err;
  EXPECT_NE(s.describe().find("relu"), std::string::npos);
}

}  // namespace
}  // namespace sn::nn
