#include "nn/activation_expr.h"

#include <cctype>
#include <charconv>
#include <cstring>
#include <map>
#include <stdexcept>
#include <tuple>

namespace sn::nn {

namespace {

const char* const kFunctions =
    "abs, acos, acosh, asin, asinh, atan (of one argument), atanh, ceil, clamp, cos, cosh, degrees, equal, exp, exp2, "
    "float, floor, fract, greaterThan, greaterThanEqual, inversesqrt, lessThan, lessThanEqual, log, log2, max, min, "
    "mix, mlp_tanh, mod, not, notEqual, pow, radians, sign, sin, sinh, smoothstep, sn_gelu_tanh, sqrt, step, tan, "
    "tanh, vec4";

struct Token {
  enum Kind { end, number, name, punct } kind = end;
  std::string text;
  double value = 0;
  int line = 1;
};

[[noreturn]] void fail(int line, const std::string& what) {
  throw std::invalid_argument("line " + std::to_string(line) + ": " + what);
}

std::vector<Token> tokenize(const std::string& s) {
  std::vector<Token> out;
  int line = 1;
  std::size_t i = 0;
  while (i < s.size()) {
    const char c = s[i];
    if (c == '\n') {
      ++line, ++i;
    } else if (std::isspace(static_cast<unsigned char>(c))) {
      ++i;
    } else if (s.compare(i, 2, "//") == 0) {
      while (i < s.size() && s[i] != '\n') ++i;
    } else if (s.compare(i, 2, "/*") == 0) {
      const std::size_t close = s.find("*/", i + 2);
      if (close == std::string::npos) fail(line, "a comment that does not end");
      for (std::size_t j = i; j < close; ++j) line += s[j] == '\n';
      i = close + 2;
    } else if (std::isdigit(static_cast<unsigned char>(c)) || (c == '.' && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1])))) {
      Token t{Token::number, "", 0, line};
      const char* first = s.data() + i;
      const std::size_t n = std::size_t(std::from_chars(first, s.data() + s.size(), t.value).ptr - first);  // any locale
      t.text = s.substr(i, n);
      i += n;
      if (i < s.size() && (s[i] == 'f' || s[i] == 'F')) ++i;  // GLSL's float suffix
      if (i < s.size() && (std::isalnum(static_cast<unsigned char>(s[i])) || s[i] == '_' || s[i] == '.'))
        fail(line, "a number the cpu backend does not read: '" + t.text + s[i] + "'");
      out.push_back(t);
    } else if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      std::size_t j = i;
      while (j < s.size() && (std::isalnum(static_cast<unsigned char>(s[j])) || s[j] == '_')) ++j;
      out.push_back({Token::name, s.substr(i, j - i), 0, line});
      i = j;
    } else {
      static const char* const two[] = {"<=", ">=", "==", "!=", "&&", "||", "+=", "-=", "*=", "/="};
      std::string p(1, c);
      for (const char* t : two)
        if (s.compare(i, 2, t) == 0) p = t;
      if (c == '.') fail(line, "'.' (a swizzle or a member) is not translated for the cpu backend");
      if (p.size() == 1 && (c == '\0' || !std::strchr("+-*/()<>!?:=,;", c)))
        fail(line, std::string("'") + c + "' is not translated for the cpu backend");
      out.push_back({Token::punct, p, 0, line});
      i += p.size();
    }
  }
  out.push_back({Token::end, "", 0, line});
  return out;
}

// A value while translating: its register (in static single assignment) and whether it is a mask.
struct Value {
  int reg = 0;
  bool mask = false;
};

struct Step {
  ExprOp op;
  int dst, a, b, c;
  float k;
};

class Translator {
 public:
  // One body's value: one expression, or statements (as nn/activation.cpp's GLSL wrapper reads
  // it: statements when it has a return). Its own names; the steps join the program's.
  int body(const std::string& text) {
    t_ = tokenize(text);
    at_ = 0;
    names_.clear();
    names_["z"] = names_["x"] = Value{0, false};
    names_["p"] = Value{1, false};
    Value result;
    if (text.find("return") == std::string::npos) {
      result = expression();
      if (peek().kind != Token::end) fail(peek().line, "'" + peek().text + "' after the expression");
    } else {
      result = statements();
    }
    if (result.mask) fail(peek().line, "the result is a bvec, not a number");
    return result.reg;
  }

  // Registers from the single assignments: z and p keep theirs; a step's value frees its
  // register after its last use.
  ActivationExpr allocate(int result, int grad) {
    std::vector<int> last(std::size_t(ssa_), -1), reg(std::size_t(ssa_), -1);
    for (std::size_t i = 0; i < steps_.size(); ++i)
      if (steps_[i].op != ExprOp::constant)
        for (int r : {steps_[i].a, steps_[i].b, steps_[i].c}) last[std::size_t(r)] = int(i);
    last[std::size_t(result)] = int(steps_.size());
    if (grad >= 0) last[std::size_t(grad)] = int(steps_.size());
    ActivationExpr e;
    reg[0] = 0, reg[1] = 1;
    std::vector<int> free;
    int registers = 2;
    for (std::size_t i = 0; i < steps_.size(); ++i) {
      const Step& s = steps_[i];
      const int a = reg[std::size_t(s.a)], b = reg[std::size_t(s.b)], c = reg[std::size_t(s.c)];
      if (s.op != ExprOp::constant)
        for (int r : {s.a, s.b, s.c})  // operands used for the last time: their registers free now
          if (r >= 2 && last[std::size_t(r)] == int(i)) {
            free.push_back(reg[std::size_t(r)]);
            last[std::size_t(r)] = -2;  // freed once, even when it is two operands
          }
      int d;
      if (!free.empty()) d = free.back(), free.pop_back();
      else d = registers++;
      if (registers > kExprRegisters)
        throw std::invalid_argument("more than " + std::to_string(kExprRegisters) +
                                    " values live at once, the most the cpu backend holds");
      reg[std::size_t(s.dst)] = d;
      e.steps.push_back({s.op, uint8_t(d), uint8_t(a), uint8_t(b), uint8_t(c), s.k});
      if (last[std::size_t(s.dst)] < 0) free.push_back(d);  // never read
    }
    e.registers = registers;
    e.result = reg[std::size_t(result)];
    e.grad = grad >= 0 ? reg[std::size_t(grad)] : -1;
    return e;
  }

 private:
  const Token& peek() const { return t_[at_]; }
  const Token& next() { return t_[at_ < t_.size() - 1 ? at_++ : at_]; }
  bool accept(const char* p) {
    if (peek().kind == Token::punct && peek().text == p) return next(), true;
    return false;
  }
  void expect(const char* p) {
    if (!accept(p)) fail(peek().line, std::string("'") + p + "' expected, got '" + peek().text + "'");
  }

  // Statements up to the first return (GLSL never runs the rest).
  Value statements() {
    for (;;) {
      const Token& t = peek();
      if (t.kind == Token::end) fail(t.line, "no return");
      if (t.kind != Token::name) fail(t.line, "'" + t.text + "' does not start a statement the cpu backend translates");
      if (t.text == "return") {
        next();
        const Value v = expression();
        expect(";");
        return v;
      }
      if (t.text == "const") next();
      const Token& head = next();
      static const char* const types[] = {"float", "vec4", "bool", "bvec4"};
      bool declared = false;
      for (const char* type : types) declared = declared || head.text == type;
      if (declared) {
        const Token& name = next();
        if (name.kind != Token::name) fail(name.line, "a name expected after '" + head.text + "'");
        expect("=");
        Value v = expression();
        if (v.mask != (head.text[0] == 'b')) fail(name.line, "'" + name.text + "' is a " + head.text + " but its value is not");
        names_[name.text] = v;
      } else {
        auto found = names_.find(head.text);
        if (found == names_.end())
          fail(head.line, "'" + head.text + "' is not translated for the cpu backend, which translates declarations of float, "
                                            "vec4, bool and bvec4, assignments and return");
        const Token& op = next();
        Value v = expression();
        if (op.text == "=") {
          if (v.mask != found->second.mask) fail(op.line, "'" + head.text + "' changes type");
          found->second = v;
        } else if (op.text == "+=" || op.text == "-=" || op.text == "*=" || op.text == "/=") {
          const char c = op.text[0];
          const ExprOp o = c == '+' ? ExprOp::add : c == '-' ? ExprOp::sub : c == '*' ? ExprOp::mul : ExprOp::div;
          found->second = arith(o, found->second, v, op.line);
        } else {
          fail(op.line, "'" + op.text + "' is not translated for the cpu backend");
        }
      }
      expect(";");
    }
  }

  // Every nesting (parentheses, arguments, signs, ?:) recurses through expression() or unary():
  // bounded, so that no text can exhaust the stack.
  struct Depth {
    int& d;
    Depth(int& depth, int line) : d(depth) {
      if (++d > kMaxDepth) fail(line, "nested more than " + std::to_string(kMaxDepth) + " deep");
    }
    ~Depth() { --d; }
  };

  Value expression() {
    const Depth depth(depth_, peek().line);
    const Value c = logical_or();
    if (!accept("?")) return c;
    const int line = peek().line;
    const Value yes = expression();
    expect(":");
    const Value no = expression();
    if (!c.mask) fail(line, "?: needs a condition");
    if (yes.mask != no.mask) fail(line, "?: of a number and a bvec");
    return emit(ExprOp::select, c, yes, no, yes.mask);
  }
  Value logical_or() {
    Value v = logical_and();
    while (peek().text == "||" && peek().kind == Token::punct) {
      const int line = next().line;
      const Value w = logical_and();
      need_masks(v, w, line, "||");
      v = emit(ExprOp::select, v, constant(1), w, true);
    }
    return v;
  }
  Value logical_and() {
    Value v = equality();
    while (peek().text == "&&" && peek().kind == Token::punct) {
      const int line = next().line;
      const Value w = equality();
      need_masks(v, w, line, "&&");
      v = emit(ExprOp::select, v, w, constant(0), true);
    }
    return v;
  }
  Value equality() {
    Value v = relational();
    for (;;) {
      const int line = peek().line;
      if (accept("==")) v = compare(ExprOp::equal, v, relational(), line);
      else if (accept("!=")) v = compare(ExprOp::not_equal, v, relational(), line);
      else return v;
    }
  }
  Value relational() {
    Value v = additive();
    for (;;) {
      const int line = peek().line;
      if (accept("<")) v = compare(ExprOp::less, v, additive(), line);
      else if (accept("<=")) v = compare(ExprOp::less_equal, v, additive(), line);
      else if (accept(">")) v = compare(ExprOp::less, additive(), v, line);
      else if (accept(">=")) v = compare(ExprOp::less_equal, additive(), v, line);
      else return v;
    }
  }
  Value additive() {
    Value v = term();
    for (;;) {
      const int line = peek().line;
      if (accept("+")) v = arith(ExprOp::add, v, term(), line);
      else if (accept("-")) v = arith(ExprOp::sub, v, term(), line);
      else return v;
    }
  }
  Value term() {
    Value v = unary();
    for (;;) {
      const int line = peek().line;
      if (accept("*")) v = arith(ExprOp::mul, v, unary(), line);
      else if (accept("/")) v = arith(ExprOp::div, v, unary(), line);
      else return v;
    }
  }
  Value unary() {
    const int line = peek().line;
    const Depth depth(depth_, line);
    if (accept("-")) return unop(ExprOp::neg, number(unary(), line, "-"));
    if (accept("+")) return number(unary(), line, "+");
    if (accept("!")) return logical_not(unary(), line);
    return primary();
  }
  Value primary() {
    const Token& t = next();
    if (t.kind == Token::number) return constant(float(t.value));
    if (accept_open(t)) {
      const Value v = expression();
      expect(")");
      return v;
    }
    if (t.kind != Token::name) fail(t.line, "'" + t.text + "' where a value was expected");
    Value v;
    if (peek().kind == Token::punct && peek().text == "(") {
      next();
      std::vector<Value> args;
      if (!accept(")")) {
        do args.push_back(expression());
        while (accept(","));
        expect(")");
      }
      v = call(t, args);
    } else {
      auto found = names_.find(t.text);
      if (found == names_.end()) fail(t.line, "'" + t.text + "' is not a name the cpu backend knows (z, x, p or a local)");
      v = found->second;
    }
    return v;
  }
  static bool accept_open(const Token& t) { return t.kind == Token::punct && t.text == "("; }

  Value call(const Token& fn, const std::vector<Value>& a) {
    const std::string& f = fn.text;
    const int line = fn.line;
    auto arity = [&](std::size_t n) {
      if (a.size() != n) fail(line, f + " takes " + std::to_string(n) + " argument" + (n == 1 ? "" : "s"));
      for (std::size_t i = 0; i < n; ++i)
        if (a[i].mask && !(f == "mix" && i == 2) && f != "not" && f != "equal" && f != "notEqual")
          fail(line, f + ": argument " + std::to_string(i + 1) + " is a bvec");
    };
    if (f == "vec4" || f == "float") {
      if (a.size() != 1) fail(line, f + " of " + std::to_string(a.size()) + " values: the cpu backend translates componentwise code only");
      return number(a[0], line, f.c_str());
    }
    static const std::map<std::string, ExprOp> unary_ops = {{"abs", ExprOp::abs}, {"floor", ExprOp::floor}, {"sqrt", ExprOp::sqrt},
                                                            {"exp", ExprOp::exp}, {"log", ExprOp::log},     {"sin", ExprOp::sin},
                                                            {"cos", ExprOp::cos}, {"tanh", ExprOp::tanh},   {"mlp_tanh", ExprOp::tanh},
                                                            {"atan", ExprOp::atan}};
    if (auto u = unary_ops.find(f); u != unary_ops.end()) return arity(1), unop(u->second, a[0]);
    if (f == "min" || f == "max") {
      arity(2);
      return arith(f == "min" ? ExprOp::min : ExprOp::max, a[0], a[1], line);
    }
    static const std::map<std::string, int> comparisons = {
        {"lessThan", 0}, {"lessThanEqual", 1}, {"greaterThan", 2}, {"greaterThanEqual", 3}, {"equal", 4}, {"notEqual", 5}};
    if (auto c = comparisons.find(f); c != comparisons.end()) {
      arity(2);
      switch (c->second) {
        case 0: return compare(ExprOp::less, a[0], a[1], line);
        case 1: return compare(ExprOp::less_equal, a[0], a[1], line);
        case 2: return compare(ExprOp::less, a[1], a[0], line);
        case 3: return compare(ExprOp::less_equal, a[1], a[0], line);
        case 4: return compare(ExprOp::equal, a[0], a[1], line);
        default: return compare(ExprOp::not_equal, a[0], a[1], line);
      }
    }
    if (f == "not") {
      arity(1);
      return logical_not(a[0], line);
    }
    const Value one = constant(1), zero = constant(0);
    auto mul = [&](Value x, Value y) { return arith(ExprOp::mul, x, y, line); };
    auto add = [&](Value x, Value y) { return arith(ExprOp::add, x, y, line); };
    auto sub = [&](Value x, Value y) { return arith(ExprOp::sub, x, y, line); };
    auto div = [&](Value x, Value y) { return arith(ExprOp::div, x, y, line); };
    auto less = [&](Value x, Value y) { return compare(ExprOp::less, x, y, line); };
    auto sel = [&](Value m, Value y, Value n) { return emit(ExprOp::select, m, y, n, false); };
    auto floor = [&](Value x) { return unop(ExprOp::floor, x); };
    auto clamp = [&](Value x, Value lo, Value hi) { return arith(ExprOp::min, arith(ExprOp::max, x, lo, line), hi, line); };
    auto sign = [&](Value x) { return sel(less(zero, x), one, sel(less(x, zero), constant(-1), zero)); };
    constexpr double kLn2 = 0.69314718055994530942, kPi = 3.14159265358979323846;
    if (f == "mix") {
      arity(3);
      if (a[2].mask) return emit(ExprOp::select, a[2], a[1], a[0], false);
      return add(mul(a[0], sub(one, a[2])), mul(a[1], a[2]));  // x (1 - a) + y a, as the GLSL spec writes it
    }
    if (f == "clamp") return arity(3), clamp(a[0], a[1], a[2]);
    if (f == "step") return arity(2), sel(less(a[1], a[0]), zero, one);
    if (f == "smoothstep") {
      arity(3);
      const Value t = clamp(div(sub(a[2], a[0]), sub(a[1], a[0])), zero, one);
      return mul(mul(t, t), sub(constant(3), mul(constant(2), t)));
    }
    if (f == "sign") return arity(1), sign(a[0]);
    if (f == "ceil") return arity(1), unop(ExprOp::neg, floor(unop(ExprOp::neg, a[0])));
    if (f == "fract") return arity(1), sub(a[0], floor(a[0]));
    if (f == "mod") return arity(2), sub(a[0], mul(a[1], floor(div(a[0], a[1]))));
    if (f == "exp2") return arity(1), unop(ExprOp::exp, mul(a[0], constant(float(kLn2))));
    if (f == "log2") return arity(1), mul(unop(ExprOp::log, a[0]), constant(float(1 / kLn2)));
    if (f == "pow") return arity(2), unop(ExprOp::exp, mul(a[1], unop(ExprOp::log, a[0])));
    if (f == "inversesqrt") return arity(1), div(one, unop(ExprOp::sqrt, a[0]));
    if (f == "tan") return arity(1), div(unop(ExprOp::sin, a[0]), unop(ExprOp::cos, a[0]));
    if (f == "sinh" || f == "cosh") {
      arity(1);
      const Value e = unop(ExprOp::exp, a[0]), ei = unop(ExprOp::exp, unop(ExprOp::neg, a[0]));
      return mul(constant(0.5f), f == "sinh" ? sub(e, ei) : add(e, ei));
    }
    auto sqrt = [&](Value x) { return unop(ExprOp::sqrt, x); };
    auto log = [&](Value x) { return unop(ExprOp::log, x); };
    if (f == "asin" || f == "acos") {
      arity(1);
      // (1 - x)(1 + x): exact factors near +-1, where 1 - x^2 cancels; at +-1, atan(+-inf).
      const Value s = unop(ExprOp::atan, div(a[0], sqrt(mul(sub(one, a[0]), add(one, a[0])))));
      return f == "asin" ? s : sub(constant(float(kPi / 2)), s);
    }
    if (f == "asinh") {  // of |x|, then the sign: no cancellation below 0
      arity(1);
      const Value m = unop(ExprOp::abs, a[0]);
      return mul(sign(a[0]), log(add(m, sqrt(add(mul(m, m), one)))));
    }
    if (f == "acosh") return arity(1), log(add(a[0], sqrt(mul(sub(a[0], one), add(a[0], one)))));
    if (f == "atanh") return arity(1), mul(constant(0.5f), log(div(add(one, a[0]), sub(one, a[0]))));
    if (f == "radians") return arity(1), mul(a[0], constant(float(kPi / 180)));
    if (f == "degrees") return arity(1), mul(a[0], constant(float(180 / kPi)));
    if (f == "sn_gelu_tanh") {  // shaders/include/mlp/activation.glsl
      arity(1);
      const Value z = a[0];
      const Value u = mul(constant(0.7978845608028654f), add(z, mul(mul(mul(constant(0.044715f), z), z), z)));
      return sel(less(constant(9), unop(ExprOp::abs, u)), sign(u), unop(ExprOp::tanh, u));
    }
    fail(line, "'" + f + "' is not translated for the cpu backend, which translates " + kFunctions);
  }

  Value number(Value v, int line, const char* what) {
    if (v.mask) fail(line, std::string(what) + " of a bvec");
    return v;
  }
  void need_masks(Value a, Value b, int line, const char* what) {
    if (!a.mask || !b.mask) fail(line, std::string(what) + " needs bvecs or bools");
  }
  Value logical_not(Value m, int line) {
    if (!m.mask) fail(line, "! and not() need a bvec");
    return emit(ExprOp::select, m, constant(0), constant(1), true);
  }
  Value arith(ExprOp op, Value a, Value b, int line) {
    if (a.mask || b.mask) fail(line, "arithmetic on a bvec");
    return emit(op, a, b, Value{}, false);
  }
  Value compare(ExprOp op, Value a, Value b, int line) {
    if (a.mask != b.mask || (a.mask && op != ExprOp::equal && op != ExprOp::not_equal)) fail(line, "a comparison of a bvec");
    return emit(op, a, b, Value{}, true);
  }
  Value unop(ExprOp op, Value a) { return emit(op, a, Value{}, Value{}, false); }

  Value constant(float k) { return emit(ExprOp::constant, Value{}, Value{}, Value{}, false, k); }
  // A step computed before (the same operation of the same values) is not computed again: f'
  // often repeats f's work (tanh, exp, 1 + |x|).
  Value emit(ExprOp op, Value a, Value b, Value c, bool mask, float k = 0.0f) {
    uint32_t bits;
    std::memcpy(&bits, &k, sizeof bits);
    const auto key = std::make_tuple(int(op), a.reg, b.reg, c.reg, bits);
    if (auto seen = done_.find(key); seen != done_.end()) return Value{seen->second, mask};
    steps_.push_back({op, ssa_, a.reg, b.reg, c.reg, k});
    done_.emplace(key, ssa_);
    return Value{ssa_++, mask};
  }

  static constexpr int kMaxDepth = 256;
  std::vector<Token> t_;
  std::size_t at_ = 0;
  int depth_ = 0;
  std::map<std::string, Value> names_;
  std::vector<Step> steps_;
  std::map<std::tuple<int, int, int, int, uint32_t>, int> done_;
  int ssa_ = 2;
};

}  // namespace

ActivationExpr translate_activation(const std::string& glsl) {
  Translator t;
  const int f = t.body(glsl);
  return t.allocate(f, -1);
}

ActivationExpr translate_activation(const std::string& glsl, const std::string& grad) {
  Translator t;
  const int f = t.body(glsl);
  const int g = t.body(grad);
  return t.allocate(f, g);
}

const char* expr_functions() { return kFunctions; }

}  // namespace sn::nn
