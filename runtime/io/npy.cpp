#include "io/npy.h"

#include <bit>
#include <cctype>
#include <cstdint>
#include <cstring>
#include <stdexcept>

namespace sn::io {

static_assert(std::endian::native == std::endian::little, "the .npy data is copied as it is: '<f4' needs a little-endian host");

namespace {

constexpr char kMagic[] = "\x93NUMPY";
constexpr std::size_t kMagicLen = 6;

// A Python literal of the header dict: a string, True/False, or a tuple of integers.
struct Value {
  enum Kind { text, boolean, tuple } kind = text;
  std::string s;
  bool b = false;
  std::vector<unsigned long long> ints;
};

// Reads numpy's header dict ("{'descr': '<f4', 'fortran_order': False, 'shape': (3, 2), }").
class HeaderParser {
 public:
  HeaderParser(const std::string& h, const std::string& name) : h_(h), name_(name) {}

  void parse(std::string* descr, bool* fortran, std::vector<unsigned long long>* shape) {
    bool has_descr = false, has_fortran = false, has_shape = false;
    expect('{');
    for (;;) {
      skip();
      if (peek() == '}') break;
      const std::string key = string_literal();
      expect(':');
      const Value v = value();
      if (key == "descr") {
        if (v.kind != Value::text) fail("'descr' is not a string");
        *descr = v.s, has_descr = true;
      } else if (key == "fortran_order") {
        if (v.kind != Value::boolean) fail("'fortran_order' is not True or False");
        *fortran = v.b, has_fortran = true;
      } else if (key == "shape") {
        if (v.kind != Value::tuple) fail("'shape' is not a tuple");
        *shape = v.ints, has_shape = true;
      } else {
        fail("unexpected key '" + key + "'");
      }
      skip();
      if (peek() == ',') {
        ++at_;
        continue;
      }
      if (peek() != '}') fail("expected ',' or '}'");
    }
    if (!has_descr || !has_fortran || !has_shape)
      fail(std::string("missing '") + (!has_descr ? "descr" : !has_fortran ? "fortran_order" : "shape") + "'");
  }

 private:
  [[noreturn]] void fail(const std::string& why) const {
    throw std::runtime_error(name_ + ": malformed .npy header (" + why + ")");
  }
  void skip() {
    while (at_ < h_.size() && std::isspace((unsigned char)h_[at_])) ++at_;
  }
  char peek() const { return at_ < h_.size() ? h_[at_] : '\0'; }
  void expect(char c) {
    skip();
    if (peek() != c) fail(std::string("expected '") + c + "'");
    ++at_;
  }
  std::string string_literal() {
    skip();
    const char q = peek();
    if (q != '\'' && q != '"') fail("expected a string");
    const std::size_t end = h_.find(q, at_ + 1);
    if (end == std::string::npos) fail("unterminated string");
    std::string s = h_.substr(at_ + 1, end - at_ - 1);
    at_ = end + 1;
    return s;
  }
  unsigned long long integer() {
    skip();
    if (!std::isdigit((unsigned char)peek())) fail("expected a non-negative integer in 'shape'");
    unsigned long long v = 0;
    while (std::isdigit((unsigned char)peek())) {
      const unsigned d = unsigned(h_[at_++] - '0');
      if (v > (~0ull - d) / 10) fail("integer too large in 'shape'");
      v = v * 10 + d;
    }
    if (peek() == 'L') ++at_;  // Python 2 longs
    return v;
  }
  Value value() {
    skip();
    Value v;
    if (peek() == '\'' || peek() == '"') {
      v.s = string_literal();
    } else if (h_.compare(at_, 4, "True") == 0) {
      v.kind = Value::boolean, v.b = true, at_ += 4;
    } else if (h_.compare(at_, 5, "False") == 0) {
      v.kind = Value::boolean, v.b = false, at_ += 5;
    } else if (peek() == '(') {
      v.kind = Value::tuple;
      ++at_;
      for (;;) {
        skip();
        if (peek() == ')') break;
        v.ints.push_back(integer());
        skip();
        if (peek() == ',') ++at_;
        else if (peek() != ')') fail("expected ',' or ')' in 'shape'");
      }
      ++at_;
    } else {
      fail("unexpected value");
    }
    return v;
  }

  const std::string& h_;
  const std::string& name_;
  std::size_t at_ = 0;
};

std::string shape_text(const std::vector<unsigned long long>& s) {
  std::string t = "(";
  for (std::size_t i = 0; i < s.size(); ++i) t += (i ? ", " : "") + std::to_string(s[i]);
  return t + (s.size() == 1 ? ",)" : ")");
}

}  // namespace

std::string npy_header(std::size_t rows, std::size_t cols) {
  // numpy/lib/format.py _write_array_header and _wrap_header: the dict in sorted key order,
  // 21 - len(repr(rows)) spaces of room to grow the first axis in place, then spaces and a
  // '\n' so that magic + version + length + header is a multiple of 64 (numpy pads by 64 when
  // it already is).
  const std::string rows_text = std::to_string(rows);
  std::string dict = "{'descr': '<f4', 'fortran_order': False, 'shape': (" + rows_text + ", " + std::to_string(cols) + "), }";
  if (rows_text.size() < 21) dict += std::string(21 - rows_text.size(), ' ');
  const std::size_t hlen = dict.size() + 1;  // with the '\n'
  const std::size_t pad = 64 - (kMagicLen + 2 + 2 + hlen) % 64;
  dict += std::string(pad, ' ') + "\n";
  if (dict.size() > 0xffff) throw std::invalid_argument("npy header too long");
  std::string out(kMagic, kMagicLen);
  out += char(1);
  out += char(0);
  out += char(dict.size() & 0xff);
  out += char(dict.size() >> 8);
  return out + dict;
}

std::string npy_bytes(const float* data, std::size_t rows, std::size_t cols) {
  std::string out = npy_header(rows, cols);
  const std::size_t head = out.size();
  out.resize(head + rows * cols * sizeof(float));
  if (rows * cols != 0) std::memcpy(out.data() + head, data, rows * cols * sizeof(float));
  return out;
}

NpyArray parse_npy(const std::string& bytes, const std::string& name) {
  if (bytes.size() < kMagicLen + 2 || bytes.compare(0, kMagicLen, kMagic, kMagicLen) != 0)
    throw std::runtime_error(name + ": not a NumPy .npy file (no \\x93NUMPY magic)");
  const int major = (unsigned char)bytes[6], minor = (unsigned char)bytes[7];
  if (major < 1 || major > 3 || minor != 0)
    throw std::runtime_error(name + ": .npy format version " + std::to_string(major) + "." + std::to_string(minor) +
                             " is not one this build reads (1.0, 2.0, 3.0)");
  const std::size_t len_size = major == 1 ? 2 : 4;
  const std::size_t prefix = kMagicLen + 2 + len_size;
  if (bytes.size() < prefix) throw std::runtime_error(name + ": truncated .npy header");
  std::size_t hlen = 0;
  for (std::size_t i = 0; i < len_size; ++i) hlen |= std::size_t((unsigned char)bytes[kMagicLen + 2 + i]) << (8 * i);
  if (bytes.size() - prefix < hlen)
    throw std::runtime_error(name + ": truncated .npy header (" + std::to_string(bytes.size()) + " bytes, the header alone needs " +
                             std::to_string(prefix + hlen) + ")");
  const std::string header = bytes.substr(prefix, hlen);

  std::string descr;
  bool fortran = false;
  std::vector<unsigned long long> shape;
  HeaderParser(header, name).parse(&descr, &fortran, &shape);
  if (descr != "<f4")
    throw std::runtime_error(name + ": dtype '" + descr + "' is not float32 ('<f4'); save the array as a.astype('<f4')");
  if (fortran)
    throw std::runtime_error(name + ": the array is in Fortran order; save a C-ordered one (numpy.ascontiguousarray)");
  if (shape.size() != 2)
    throw std::runtime_error(name + ": shape " + shape_text(shape) + " is not 2-D (rows, columns)");

  NpyArray a;
  a.rows = shape[0];
  a.cols = shape[1];
  const std::size_t data = bytes.size() - prefix - hlen;
  if (a.cols != 0 && a.rows > (~std::size_t(0) / sizeof(float)) / a.cols)
    throw std::runtime_error(name + ": shape " + shape_text(shape) + " is too large");
  const std::size_t need = a.rows * a.cols * sizeof(float);
  if (data != need)
    throw std::runtime_error(name + ": " + std::to_string(data) + " data bytes, but shape " + shape_text(shape) +
                             " of float32 needs " + std::to_string(need) + (data < need ? " (truncated)" : ""));
  a.data.resize(a.rows * a.cols);
  if (need) std::memcpy(a.data.data(), bytes.data() + prefix + hlen, need);
  return a;
}

}  // namespace sn::io
