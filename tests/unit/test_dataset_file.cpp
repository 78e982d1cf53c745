// Dataset files (io/npy.h, data/dataset_file.h): the .npy header byte for byte as numpy.save
// writes it, round trips that keep every bit, and a clear error for every damaged file.
#include <gtest/gtest.h>

#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cfloat>
#include <cmath>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>

#include "data/dataset_file.h"
#include "io/npy.h"
#include "io/read_file.h"
#include "io/temp_dir.h"
#include "message_of.h"

namespace sn::data {
namespace {

namespace fs = std::filesystem;

std::string scratch(const std::string& name) {
  static const sn::io::TempDir dir("test_dataset_file");  // removed at exit
  return (fs::path(dir.path()) / name).string();
}

void write(const std::string& path, const std::string& bytes) {
  std::ofstream f(path, std::ios::binary);
  f << bytes;
}

bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0);
}

// Values a text format could lose: signed zero, subnormals, the extremes, long mantissas.
Dataset awkward(std::vector<std::string> names = {"normal", "uv"}, shading::ColorSpace color = shading::ColorSpace::hsv) {
  Dataset d;
  d.inputs = 5;
  d.outputs = 3;
  d.color = color;
  d.input_names = std::move(names);
  d.key = "dataset-0123456789abcdef";
  const float special[] = {-0.0f, 1e-45f, FLT_MIN / 2, FLT_MIN, FLT_MAX, -FLT_MAX, 0.1f, 1.0f / 3, 16777217.0f, 3.14159274f};
  for (int r = 0; r < 7; ++r)
    for (int k = 0; k < 5; ++k) (r < 5 ? d.train_x : d.val_x).push_back(special[(r * 5 + k) % 10] * (k % 2 ? -1 : 1));
  for (int r = 0; r < 7; ++r)
    for (int k = 0; k < 3; ++k) (r < 5 ? d.train_y : d.val_y).push_back(std::nextafter(float(r) / 7, 2.0f) + float(k));
  return d;
}

void expect_equal(const Dataset& a, const Dataset& b) {
  EXPECT_EQ(a.inputs, b.inputs);
  EXPECT_EQ(a.outputs, b.outputs);
  EXPECT_EQ(a.color, b.color);
  EXPECT_EQ(a.input_names, b.input_names);
  EXPECT_TRUE(same_bits(a.train_x, b.train_x));
  EXPECT_TRUE(same_bits(a.train_y, b.train_y));
  EXPECT_TRUE(same_bits(a.val_x, b.val_x));
  EXPECT_TRUE(same_bits(a.val_y, b.val_y));
}

// ---- .npy ----

TEST(Npy, HeaderIsByteForByteWhatNumpySaveWrites) {
  // numpy 1.24.2: io.BytesIO after np.save(b, np.zeros((3, 2), '<f4')): 128 bytes before the data.
  const std::string dict = "{'descr': '<f4', 'fortran_order': False, 'shape': (3, 2), }";
  const std::string expect = std::string("\x93NUMPY\x01\x00\x76\x00", 10) + dict + std::string(58, ' ') + "\n";
  EXPECT_EQ(io::npy_header(3, 2), expect);
  // (64149, 6): 54 spaces; (12345678901234567, 3): 42 (numpy's room to grow the first axis shrinks).
  EXPECT_EQ(io::npy_header(64149, 6),
            std::string("\x93NUMPY\x01\x00\x76\x00", 10) + "{'descr': '<f4', 'fortran_order': False, 'shape': (64149, 6), }" +
                std::string(54, ' ') + "\n");
  EXPECT_EQ(io::npy_header(12345678901234567ull, 3).size(), 128u);
  EXPECT_EQ(io::npy_header(12345678901234567ull, 3).substr(10 + 75, 42), std::string(42, ' '));
}

TEST(Npy, RoundTripKeepsEveryBit) {
  const std::vector<float> v = {-0.0f, 1e-45f, FLT_MAX, 0.1f, -2.5f, 7.0f};
  const std::string bytes = io::npy_bytes(v.data(), 3, 2);
  EXPECT_EQ(bytes.size(), 128u + 24u);
  io::NpyArray a = io::parse_npy(bytes, "a.npy");
  EXPECT_EQ(a.rows, 3u);
  EXPECT_EQ(a.cols, 2u);
  EXPECT_TRUE(same_bits(a.data, v));
}

TEST(Npy, ForeignAndDamagedFilesAreClearErrors) {
  const std::vector<float> v = {1, 2, 3, 4, 5, 6};
  const std::string good = io::npy_bytes(v.data(), 3, 2);
  auto with_dict = [&](const std::string& dict) {
    std::string h = dict + std::string(117 - dict.size(), ' ') + "\n";
    return std::string("\x93NUMPY\x01\x00\x76\x00", 10) + h + good.substr(128);
  };
  auto err = [](const std::string& bytes) { return message_of([&] { io::parse_npy(bytes, "a.npy"); }); };
  EXPECT_EQ(err("PK\x03\x04 not numpy"), "a.npy: not a NumPy .npy file (no \\x93NUMPY magic)");
  std::string v9 = good;
  v9[6] = 9;
  EXPECT_EQ(err(v9), "a.npy: .npy format version 9.0 is not one this build reads (1.0, 2.0, 3.0)");
  EXPECT_EQ(err(good.substr(0, 60)), "a.npy: truncated .npy header (60 bytes, the header alone needs 128)");
  EXPECT_EQ(err(good.substr(0, good.size() - 3)), "a.npy: 21 data bytes, but shape (3, 2) of float32 needs 24 (truncated)");
  EXPECT_EQ(err(good + "xx"), "a.npy: 26 data bytes, but shape (3, 2) of float32 needs 24");
  EXPECT_EQ(err(with_dict("{'descr': '<f8', 'fortran_order': False, 'shape': (3, 2), }")),
            "a.npy: dtype '<f8' is not float32 ('<f4'); save the array as a.astype('<f4')");
  EXPECT_EQ(err(with_dict("{'descr': '>f4', 'fortran_order': False, 'shape': (3, 2), }")),
            "a.npy: dtype '>f4' is not float32 ('<f4'); save the array as a.astype('<f4')");
  EXPECT_EQ(err(with_dict("{'descr': '<f4', 'fortran_order': True, 'shape': (3, 2), }")),
            "a.npy: the array is in Fortran order; save a C-ordered one (numpy.ascontiguousarray)");
  EXPECT_EQ(err(with_dict("{'descr': '<f4', 'fortran_order': False, 'shape': (6,), }")),
            "a.npy: shape (6,) is not 2-D (rows, columns)");
  EXPECT_EQ(err(with_dict("{'descr': '<f4', 'fortran_order': False, 'shape': (1, 3, 2), }")),
            "a.npy: shape (1, 3, 2) is not 2-D (rows, columns)");
  EXPECT_EQ(err(with_dict("{'descr': '<f4', 'fortran_order': False, }")), "a.npy: malformed .npy header (missing 'shape')");
  EXPECT_EQ(err(with_dict("{'descr': '<f4, 'fortran_order': False, 'shape': (3, 2), }")),
            "a.npy: malformed .npy header (expected ',' or '}')");
  // Keys in another order and without the trailing comma are still numpy's format.
  io::NpyArray a = io::parse_npy(with_dict("{'shape': (3, 2), \"fortran_order\": False, 'descr': '<f4'}"), "a.npy");
  EXPECT_TRUE(same_bits(a.data, v));
}

// ---- whole datasets ----

TEST(DatasetFile, PathsPickTheFormat) {
  EXPECT_EQ(dataset_paths("out/cloth.json").inputs, "out/cloth.inputs.npy");
  EXPECT_EQ(dataset_paths("out/cloth.json").targets, "out/cloth.targets.npy");
  EXPECT_EQ(dataset_paths("out/cloth").main, "out/cloth.json");
  EXPECT_EQ(dataset_paths("out/cloth").inputs, "out/cloth.inputs.npy");
  EXPECT_EQ(dataset_paths("x.csv").format, DatasetFormat::csv);
  EXPECT_EQ(message_of([] { dataset_paths("out/cloth.npy"); }),
            "'out/cloth.npy': unknown dataset file type '.npy' (.json: NumPy arrays with a JSON sidecar; .csv; no extension: .json)");
  EXPECT_EQ(message_of([] { dataset_paths("out/"); }),
            "'out/' names no file (expected e.g. out/cloth.json, out/cloth.csv or out/cloth)");
}

TEST(DatasetFile, NumpyRoundTripIsBitExact) {
  const Dataset d = awkward();
  const std::string at = scratch("np/awkward");
  DatasetPaths p = export_dataset(d, at);
  EXPECT_EQ(p.main, at + ".json");
  auto back = load_dataset(p.main);
  expect_equal(d, *back);
  // Training rows first, then validation rows, in one array each.
  io::NpyArray x = io::parse_npy(io::read_file(p.inputs), p.inputs);
  EXPECT_EQ(x.rows, 7u);
  EXPECT_EQ(x.cols, 5u);
  EXPECT_EQ(std::memcmp(x.data.data() + 25, d.val_x.data(), 10 * sizeof(float)), 0);
  const std::string side = io::read_file(p.main);
  EXPECT_NE(side.find("\"format\": \"shadenet-dataset\""), std::string::npos) << side;
  EXPECT_NE(side.find("\"file\": \"awkward.inputs.npy\""), std::string::npos) << side;
  EXPECT_NE(side.find("\"source_key\": \"dataset-0123456789abcdef\""), std::string::npos) << side;
  EXPECT_NE(side.find("\"train\": 5"), std::string::npos) << side;
}

TEST(DatasetFile, CsvRoundTripIsBitExact) {
  for (auto color : {shading::ColorSpace::rgb, shading::ColorSpace::hsv, shading::ColorSpace::cie_xyz, shading::ColorSpace::cie_lab}) {
    const Dataset d = awkward({"normal", "uv"}, color);
    const std::string at = scratch("awkward.csv");
    export_dataset(d, at);
    expect_equal(d, *load_dataset(at));
  }
  Dataset unnamed = awkward({});
  export_dataset(unnamed, scratch("unnamed.csv"));
  expect_equal(unnamed, *load_dataset(scratch("unnamed.csv")));
}

TEST(DatasetFile, CsvColumns) {
  EXPECT_EQ(csv_header(awkward({"normal", "uv"}, shading::ColorSpace::rgb)), "normal_x,normal_y,normal_z,uv_u,uv_v,r,g,b,set");
  EXPECT_EQ(csv_header(awkward({}, shading::ColorSpace::cie_lab)), "x1,x2,x3,x4,x5,L,a,b,set");
  EXPECT_EQ(csv_header(awkward({"uv", "world_position"}, shading::ColorSpace::cie_xyz)),
            "uv_u,uv_v,world_position_x,world_position_y,world_position_z,X,Y,Z,set");
  Dataset one = awkward({}, shading::ColorSpace::rgb);
  one.outputs = 1;
  EXPECT_EQ(csv_header(one), "x1,x2,x3,x4,x5,y1,set");
  const std::string at = scratch("small.csv");
  write(at, "x1,y1,y2\n0.5,1,2\n-1e-3, 3 ,4\r\n\n");
  auto d = load_dataset(at);
  EXPECT_EQ(d->outputs, 2);
  EXPECT_EQ(d->train_count(), 2u);  // no set column: every row trains
  EXPECT_EQ(d->train_x, (std::vector<float>{0.5f, -1e-3f}));
  EXPECT_EQ(d->train_y, (std::vector<float>{1, 2, 3, 4}));
  Dataset odd = awkward({"normal", "shading"});
  EXPECT_NE(message_of([&] { csv_header(odd); }).find("CSV column names cannot carry these inputs: input name 'shading'"),
            std::string::npos);
  // A varied parameter's column (it was written as roughness_x, with no range, and the reader
  // refused the file it had written).
  Dataset varied = awkward({"normal", "roughness", "k"});
  varied.conditions = {{"roughness", 0.1, 0.8}, {"k", 0, 1}};
  EXPECT_EQ(message_of([&] { csv_header(varied); }),
            "CSV column names cannot carry the varied parameter 'roughness' and its range (use .json: the NumPy "
            "sidecar keeps them)");
  const std::string json = scratch("varied.json");
  export_dataset(varied, json);
  EXPECT_EQ(load_dataset(json)->conditions, varied.conditions);
}

// Input names and varied parameters a sidecar gives are checked as sn.dataset{} checks them:
// names that do not fit the rows trained, then made a checkpoint sn.load refused.
TEST(DatasetFile, SidecarNamesMustFitTheRows) {
  Dataset varied = awkward({"normal", "roughness", "k"});
  varied.conditions = {{"roughness", 0.25, 0.75}, {"k", 0, 1}};
  const std::string at = scratch("names/s.json");
  export_dataset(varied, at);
  const std::string good = io::read_file(at);
  // Replaces the first `from` after `after` in the sidecar and loads it.
  auto load_err = [&](const std::string& after, const std::string& from, const std::string& to) {
    std::string t = good;
    const auto i = t.find(from, t.find(after));
    EXPECT_NE(i, std::string::npos) << from;
    write(at, t.replace(i, from.size(), to));
    return message_of([&] { load_dataset(at); });
  };
  EXPECT_EQ(load_err("\"names\"", "\"k\"", "\"view\""),
            at + ": field 'inputs': varied parameter 'k' is not among the input names {normal, roughness, view}");
  EXPECT_EQ(load_err("\"names\"", "\"roughness\"", "\"uv\""),
            at + ": field 'inputs': varied parameter 'roughness' is not among the input names {normal, uv, k}");
  EXPECT_EQ(load_err("\"conditions\"", "0.25", "0.9"),
            at + ": field 'inputs': varied parameter 'roughness' has the range [0.9, 0.75]; a finite range with min <= max expected");
  EXPECT_EQ(load_err("\"names\"", "\"normal\"", "\"k\""), at + ": field 'inputs': input name 'k' is listed twice");
  EXPECT_EQ(load_err("\"conditions\"", "\"k\"", "\"normal\""),
            at + ": field 'inputs': varied parameter 'normal' is a G-buffer attribute, not a parameter");
  write(at, good);
  EXPECT_EQ(load_dataset(at)->conditions, varied.conditions);
}

TEST(DatasetFile, KeyIsTheContentsHash) {
  const Dataset d = awkward();
  export_dataset(d, scratch("k.csv"));
  export_dataset(d, scratch("k.json"));
  const std::string a = load_dataset(scratch("k.csv"))->key, b = load_dataset(scratch("k.json"))->key;
  EXPECT_EQ(a, b);
  EXPECT_EQ(a.rfind("file-", 0), 0u);
  Dataset e = d;
  e.train_y[4] = 0.25f;
  export_dataset(e, scratch("k.json"));
  EXPECT_NE(load_dataset(scratch("k.json"))->key, a);
}

TEST(DatasetFile, SidecarErrorsNameTheFileAndField) {
  const Dataset d = awkward();
  const std::string at = scratch("side/s.json");
  auto p = export_dataset(d, at);
  const std::string good = io::read_file(at);
  auto load_err = [&](const std::string& text) {
    write(at, text);
    return message_of([&] { load_dataset(at); });
  };
  auto edit = [&](const std::string& from, const std::string& to) {
    std::string t = good;
    const auto i = t.find(from);
    EXPECT_NE(i, std::string::npos) << from;
    return t.replace(i, from.size(), to);
  };
  EXPECT_EQ(load_err("{\"format\": "), at + ": malformed JSON: [json.exception.parse_error.101] parse error at line 1, column 12: "
                                            "syntax error while parsing value - unexpected end of input; expected '[', '{', or a literal");
  EXPECT_EQ(load_err("[1]"), at + ": not a dataset sidecar (a JSON object expected)");
  EXPECT_EQ(load_err(edit("\"format\": \"shadenet-dataset\",", "")), at + ": missing field 'format'");
  EXPECT_EQ(load_err(edit("shadenet-dataset", "other")),
            at + ": not a shadenet dataset sidecar (format 'other', expected 'shadenet-dataset')");
  EXPECT_EQ(load_err(edit("\"version\": 1", "\"version\": 2")), at + ": dataset file version 2; this build reads version 1");
  EXPECT_EQ(load_err(edit("\"train\": 5", "\"train\": \"5\"")), at + ": field 'rows.train' must be an integer of at least 1, got \"5\"");
  EXPECT_EQ(load_err(edit("\"val\": 2", "\"val\": -2")), at + ": field 'rows.val' must be an integer of at least 0, got -2");
  EXPECT_EQ(load_err(edit("\"train\": 5", "\"train\": 18446744073709551615")), at + ": more than 2^31 rows in a set");
  EXPECT_EQ(load_err(edit("\"width\": 5,", "")), at + ": missing field 'inputs.width'");
  EXPECT_EQ(load_err(edit("\"color\": \"hsv\"", "\"color\": \"cmyk\"")),
            at + ": field 'targets.color': unknown colour space 'cmyk' (valid: rgb, hsv, cie, cie_xyz, cie_lab)");
  EXPECT_EQ(load_err(edit("\"val\": 2", "\"val\": 3")),
            p.inputs + ": shape (7, 5) does not match the sidecar " + at + ": (8, 5) (rows.train + rows.val, inputs.width)");
  EXPECT_EQ(load_err(edit("s.targets.npy", "gone.npy")),
            "cannot read dataset array '" + scratch("side/gone.npy") + "': no such file");
  write(at, good);
  EXPECT_EQ(message_of([&] { load_dataset(scratch("side/none.json")); }),
            "cannot read dataset '" + scratch("side/none.json") + "': no such file");
  const std::string fifo = scratch("side/fifo.json");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);  // no writer: opening it must not wait for one
  EXPECT_EQ(message_of([&] { load_dataset(fifo); }), "cannot read dataset '" + fifo + "': not a regular file");
  fs::create_directories(scratch("side/dir.json"));
  EXPECT_EQ(message_of([&] { load_dataset(scratch("side/dir.json")); }),
            "cannot read dataset '" + scratch("side/dir.json") + "': it is a directory");
  // A NaN in an array names its row and column.
  Dataset nan = d;
  nan.val_x[6] = std::numeric_limits<float>::quiet_NaN();
  nan.val_x[7] = 1;
  auto q = export_dataset(nan, scratch("side/nan"));
  EXPECT_EQ(message_of([&] { load_dataset(q.main); }), q.inputs + ": row 7 column 2 is NaN");
}

TEST(DatasetFile, CsvErrorsNameFileAndLine) {
  const std::string at = scratch("bad.csv");
  auto err = [&](const std::string& text) {
    write(at, text);
    return message_of([&] { load_dataset(at); });
  };
  EXPECT_EQ(err(""), at + ": empty file (a header line expected)");
  EXPECT_EQ(err("x1,r,g,b,set\n1,2,3,4,train\n1,2,3,train\n"), at + ":3: 4 columns, the header has 5");
  EXPECT_EQ(err("x1,r,g,b,set\n1,2,3,4,train\n\n1,2,abc,4,val\n"), at + ":4: column 'g': 'abc' is not a number");
  EXPECT_EQ(err("x1,r,g,b,set\n1,2,,4,train\n"), at + ":2: column 'g': '' is not a number");
  EXPECT_EQ(err("x1,r,g,b,set\n1,2,nan,4,train\n"), at + ":2: column 'g' is NaN");
  EXPECT_EQ(err("x1,r,g,b,set\n1,2,-inf,4,train\n"), at + ":2: column 'g' is infinite");
  EXPECT_EQ(err("x1,r,g,b,set\n1,2,1e39,4,train\n"), at + ":2: column 'g': 1e39 is outside float32's range");
  EXPECT_EQ(err("x1,r,g,b,set\n1,2,3,4,test\n"), at + ":2: set 'test' is neither train nor val");
  EXPECT_EQ(err("x1,r,g,b,set\n1,2,3,4,val\n"), at + ": no training rows (every row is set = val)");
  EXPECT_EQ(err("x1,r,g,b,set\n"), at + ": no training rows (no data lines)");
  EXPECT_EQ(err("x1,red,green,blue,set\n"),
            at + ":1: cannot tell the target columns: the header must end in r,g,b / h,s,v / X,Y,Z / L,a,b / y1..ym, then set");
  EXPECT_EQ(err("r,g,b,set\n"), at + ":1: no input columns before the targets");
  EXPECT_NE(err("colour,r,g,b,set\n1,2,3,4,train\n").find(at + ":1: input column 'colour' is not <attribute>_<component>"),
            std::string::npos);
  EXPECT_EQ(err("normal_x,normal_z,normal_y,r,g,b,set\n"),
            at + ":1: input 'normal' needs the columns normal_x..normal_z in order; column 2 is 'normal_z', expected 'normal_y'");
}

// What spreadsheets write: a UTF-8 byte order mark before the header (it became part of the first
// column's name, which no input was then called), and a value too small for a float (refused as
// "outside float32's range"), which rounds to 0 as a cast does.
TEST(DatasetFile, CsvFromSpreadsheets) {
  const std::string at = scratch("excel.csv");
  write(at, "\xEF\xBB\xBFnormal_x,normal_y,normal_z,r,g,b,set\n1e-50,1,0,0.5,0.5,0.5,train\n0,0,1,0.1,0.2,0.3,val\n");
  auto d = load_dataset(at);
  ASSERT_EQ(d->input_names, std::vector<std::string>{"normal"});
  EXPECT_EQ(d->train_x[0], 0.0f);
  EXPECT_EQ(d->train_x[1], 1.0f);
}

TEST(DatasetFile, UnwritablePathLeavesNothingBehind) {
  const std::string blocker = scratch("blocker");
  write(blocker, "a file, so nothing can be written below it");
  const Dataset d = awkward();
  EXPECT_EQ(message_of([&] { export_dataset(d, blocker + "/sub/x.json"); }),
            "cannot write dataset '" + blocker + "/sub/x.inputs.npy': cannot create folder '" + blocker +
                "/sub': Not a directory");
  EXPECT_EQ(message_of([&] { export_dataset(d, blocker + "/x.csv"); }),
            "cannot write dataset '" + blocker + "/x.csv': cannot create folder '" + blocker + "': Not a directory");
  // A folder where an array goes is refused before anything is written: the old export stays as
  // it was. (A rename that fails all the same leaves no sidecar: the old one is removed before the
  // renames, AtomicWrite.ARenameThatFailsLeavesTheRestOld.)
  const std::string at = scratch("again/a.json");
  export_dataset(d, at);
  ASSERT_TRUE(fs::exists(at));
  fs::remove(scratch("again/a.targets.npy"));
  fs::create_directories(scratch("again/a.targets.npy/x"));
  EXPECT_EQ(message_of([&] { export_dataset(d, at); }),
            "cannot write dataset '" + scratch("again/a.targets.npy") + "': it is a directory");
  EXPECT_TRUE(fs::exists(at));
  for (const auto& e : fs::directory_iterator(scratch("again"))) EXPECT_NE(e.path().filename().string()[0], '.') << e.path();
}

// A sidecar path that is a link to another folder's sidecar: the export goes where the link points
// (the arrays beside the real sidecar, named after it), the link stays, and loading through the
// link finds the arrays. The link was removed and the arrays written beside it, the sidecar where
// it pointed: neither path loaded.
TEST(DatasetFile, ExportThroughALinkGoesWhereItPoints) {
  const fs::path out = scratch("linked/out"), real = scratch("linked/real");
  fs::create_directories(out);
  fs::create_directories(real);
  const fs::path link = out / "ds.json";
  fs::create_symlink(fs::path("..") / "real" / "cloth.json", link);
  for (int pass = 0; pass < 2; ++pass) {  // the target missing, then there
    Dataset d = awkward();
    d.train_x[0] = float(pass);
    const DatasetPaths p = export_dataset(d, link.string());
    EXPECT_EQ(p.main, link.string());
    EXPECT_EQ(p.inputs, (out / ".." / "real" / "cloth.inputs.npy").string());
    EXPECT_TRUE(fs::is_symlink(link));
    EXPECT_TRUE(fs::is_regular_file(fs::symlink_status(real / "cloth.json")));
    EXPECT_TRUE(fs::exists(real / "cloth.inputs.npy"));
    EXPECT_TRUE(fs::exists(real / "cloth.targets.npy"));
    EXPECT_FALSE(fs::exists(out / "ds.inputs.npy"));
    expect_equal(d, *load_dataset(link.string()));
    expect_equal(d, *load_dataset((real / "cloth.json").string()));
  }
}

// Arrays beside a sidecar that are not the ones exported with it (another export's, copied in by
// hand or left by a kill) are refused by their content key: they loaded as a mix of two datasets.
TEST(DatasetFile, ArraysFromAnotherExportAreRefused) {
  const std::string at = scratch("mixed/m.json");
  Dataset a = awkward(), b = awkward();
  b.train_y[0] = 0.75f;
  const DatasetPaths p = export_dataset(a, at);
  const std::string a_targets = io::read_file(p.targets);
  export_dataset(b, at);
  expect_equal(b, *load_dataset(at));
  write(p.targets, a_targets);
  const std::string err = message_of([&] { load_dataset(at); });
  EXPECT_EQ(err.rfind(at + ": its arrays m.inputs.npy and m.targets.npy do not hold the rows it was exported with "
                           "(content_key file-", 0), 0u) << err;
  EXPECT_NE(err.find("export the dataset again (if the arrays were changed on purpose, remove content_key from the "
                     "sidecar)"), std::string::npos) << err;
  // A sidecar without the key (written by another tool, or before it was recorded) loads as before.
  std::string side = io::read_file(at);
  const auto k = side.find(",\n  \"content_key\"");
  ASSERT_NE(k, std::string::npos);
  write(at, side.erase(k, side.find('"', side.find(": \"", k) + 3) + 1 - k));
  EXPECT_EQ(load_dataset(at)->train_y[0], a.train_y[0]);
}

// Two datasets of `rows` rows that differ in every row, and tell which one a loaded set is.
Dataset numbered_rows(std::size_t rows, float tag) {
  Dataset d;
  d.inputs = 6;
  d.outputs = 3;
  d.key = "dataset-test";
  for (std::size_t r = 0; r < rows; ++r) {
    auto& x = r < rows * 4 / 5 ? d.train_x : d.val_x;
    auto& y = r < rows * 4 / 5 ? d.train_y : d.val_y;
    for (int k = 0; k < 6; ++k) x.push_back(tag + float(r % 1000) * 1e-3f + float(k));
    for (int k = 0; k < 3; ++k) y.push_back(tag * 2 + float(r % 977) * 1e-3f);
  }
  return d;
}

// A child process that exports `d` (and `e`, alternately, when given) to `at` until it is killed.
pid_t exporting(const Dataset& d, const Dataset* e, const std::string& at) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    for (long i = 0;; ++i) {
      try {
        export_dataset(e && i % 2 ? *e : d, at);
      } catch (...) {
        ::_exit(3);
      }
    }
  }
  return pid;
}

void stop(pid_t pid) {
  ::kill(pid, SIGKILL);
  int status = 0;
  ::waitpid(pid, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status)) << "the exporter ended by itself (status " << status << "): an export failed";
}

// Which of a and b the dataset at `at` is: 'a', 'b', or '?' (a mix, or an error: `why`).
char which(const std::string& at, const Dataset& a, const Dataset& b, std::string* why) {
  try {
    auto l = load_dataset(at);
    const bool is_a = same_bits(l->train_x, a.train_x) && same_bits(l->val_y, a.val_y);
    const bool is_b = same_bits(l->train_x, b.train_x) && same_bits(l->val_y, b.val_y);
    if (is_a || is_b) return is_a ? 'a' : 'b';
    *why = "a mix of both exports";
  } catch (const std::exception& ex) {
    *why = ex.what();
  }
  return '?';
}

// SIGKILL at any moment of re-exports leaves a whole export, the old or the new: the old sidecar
// was removed before the renames, and a third of kills left none. The next export removes what
// the killed ones left (their temporaries, the old arrays kept aside).
TEST(DatasetFile, AKillAtAnyMomentLeavesAWholeExport) {
  const std::string at = scratch("killed/k.json");
  const Dataset a = numbered_rows(100000, 1), b = numbered_rows(100000, 2);
  export_dataset(a, at);
  const auto t0 = std::chrono::steady_clock::now();
  export_dataset(b, at);
  const double one = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  int bad = 0;
  for (int trial = 0; trial < 40; ++trial) {
    const pid_t pid = exporting(a, &b, at);
    // Kill times spread over about two exports, a different phase each trial.
    ::usleep(useconds_t(1e6 * one * 2 * ((trial * 37) % 40) / 40.0) + 200);
    stop(pid);
    std::string why;
    if (which(at, a, b, &why) == '?') {
      ++bad;
      ADD_FAILURE() << "trial " << trial << ": " << why;
    }
    if (bad > 2) break;
  }
  export_dataset(a, at);
  for (const auto& e : fs::directory_iterator(scratch("killed")))
    EXPECT_NE(e.path().filename().string()[0], '.') << "left behind: " << e.path();
}

// Two processes exporting to one path and a third loading from it: every load is one export whole
// (a reader took one's inputs with the other's targets, without an error), and no export fails
// ("cannot remove the old sidecar: Success", when the other had just removed it).
TEST(DatasetFile, ConcurrentExportsAndLoadsNeverMix) {
  const std::string at = scratch("concurrent/c.json");
  const Dataset a = numbered_rows(20000, 1), b = numbered_rows(20000, 2);
  export_dataset(a, at);
  const pid_t pa = exporting(a, nullptr, at), pb = exporting(b, nullptr, at);
  int seen[2] = {0, 0}, bad = 0;
  const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(1500);
  while (std::chrono::steady_clock::now() < until && bad < 3) {
    std::string why;
    const char w = which(at, a, b, &why);
    if (w == '?') {
      ++bad;
      ADD_FAILURE() << why;
    } else {
      ++seen[w - 'a'];
    }
  }
  stop(pa);
  stop(pb);
  EXPECT_GT(seen[0] + seen[1], 10);
}

}  // namespace
}  // namespace sn::data
