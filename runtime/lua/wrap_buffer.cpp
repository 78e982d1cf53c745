// sn.buffer{...}: typed GPU storage buffers. Indices are 1-based like every Lua array.
#include <cmath>
#include <cstring>

#include "gl/buffer.h"
#include "io/text.h"
#include "lua/binding.h"
#include "lua/module.h"

namespace sn::lua {

namespace {

constexpr const char* kType = "Buffer";
using gl::Buffer;

Buffer& self(lua_State* L) { return check<Buffer>(L, 1, kType); }

// One integer component, exactly: a value with a fraction or outside the type's range is an
// error (3e9 wrapped to -2147483648 in an int32 buffer, 1.7 became 1).
uint32_t integer_component(double v, bool is_signed, const std::string& what) {
  const double lo = is_signed ? -2147483648.0 : 0.0, hi = is_signed ? 2147483647.0 : 4294967295.0;
  if (!(v == std::floor(v) && v >= lo && v <= hi))
    throw Error(what + ": " + io::number_text(v) + " is not an integer in " +
                (is_signed ? "[-2147483648, 2147483647], the range of int32" : "[0, 4294967295], the range of uint32"));
  return is_signed ? uint32_t(int32_t(v)) : uint32_t(v);
}

// Reads element `e` (0-based) from Lua value at idx into `out` (components() scalars).
void to_components(lua_State* L, int idx, const gl::ElemInfo& info, uint32_t* out, const std::string& what) {
  auto put = [&](int c, double v) {
    if (info.is_float) {
      float f = float(v);
      std::memcpy(&out[c], &f, 4);
    } else {
      out[c] = integer_component(v, info.is_signed, what);
    }
  };
  if (info.components == 1) {
    put(0, check_number(L, idx, what.c_str()));
  } else {
    auto v = check_numbers(L, idx, what.c_str(), info.components);
    for (int c = 0; c < info.components; ++c) put(c, v[c]);
  }
}

void push_components(lua_State* L, const gl::ElemInfo& info, const uint32_t* in) {
  auto get = [&](int c) -> double {
    if (info.is_float) {
      float f;
      std::memcpy(&f, &in[c], 4);
      return f;
    }
    return info.is_signed ? double(int32_t(in[c])) : double(in[c]);
  };
  if (info.components == 1) {
    lua_pushnumber(L, get(0));
    return;
  }
  lua_createtable(L, info.components, 0);
  for (int c = 0; c < info.components; ++c) {
    lua_pushnumber(L, get(c));
    lua_rawseti(L, -2, c + 1);
  }
}

// Reads a Lua array of elements into packed components.
std::vector<uint32_t> table_to_components(lua_State* L, int idx, const gl::ElemInfo& info, const char* what) {
  const int n = check_list(L, idx, what);
  std::vector<uint32_t> data(size_t(n) * info.components);
  for (int i = 1; i <= n; ++i) {
    lua_rawgeti(L, idx, i);
    to_components(L, -1, info, &data[size_t(i - 1) * info.components], std::string(what) + " element " + std::to_string(i));
    lua_pop(L, 1);
  }
  return data;
}

size_t check_index(lua_State* L, int idx, const Buffer& b) {
  long long i = check_integer(L, idx, "buffer index");
  if (i < 1 || size_t(i) > b.count())
    throw Error("buffer index " + std::to_string(i) + " out of range 1.." + std::to_string(b.count()));
  return size_t(i - 1);
}

// sn.buffer{ type = "float32", size = N } or sn.buffer{ type = "vec4", data = {...} }
int w_new(lua_State* L) {
  Options o(L, 1, "sn.buffer", {"type", "size", "data", "fill"});
  gl::ElemType t = gl::parse_elem_type(o.string("type", "float32"));
  const auto& info = gl::elem_info(t);
  std::vector<uint32_t> data;
  if (o.has("data")) {
    int i = o.push("data");
    if (!lua_istable(L, i)) throw Error("sn.buffer option 'data': table expected, got " + type_name_at(L, i));
    data = table_to_components(L, i, info, "sn.buffer option 'data'");
    lua_pop(L, 1);
  }
  long long n = o.integer("size", (long long)(data.size() / info.components));
  if (n < 1) throw Error("sn.buffer: size must be at least 1, got " + std::to_string(n) + " (give 'size' or 'data')");
  if (!data.empty() && size_t(n) * info.components < data.size())
    throw Error("sn.buffer: 'data' has more elements than 'size'");
  auto b = std::make_shared<Buffer>(t, size_t(n));
  if (o.has("fill")) {
    double v = o.number("fill", 0);
    if (info.is_float) b->fill_float(float(v));
    else b->fill_uint(integer_component(v, info.is_signed, "sn.buffer option 'fill'"));
  }
  if (!data.empty()) b->upload(data.data(), 0, data.size());
  push(L, std::move(b), kType);
  return 1;
}

int w_size(lua_State* L) {
  lua_pushinteger(L, lua_Integer(self(L).count()));
  return 1;
}

int w_type(lua_State* L) {
  lua_pushstring(L, gl::elem_info(self(L).type()).name);
  return 1;
}

int w_get(lua_State* L) {
  Buffer& b = self(L);
  size_t i = check_index(L, 2, b);
  const auto& info = gl::elem_info(b.type());
  uint32_t v[4];
  b.download(v, i * info.components, info.components);
  push_components(L, info, v);
  return 1;
}

int w_set(lua_State* L) {
  Buffer& b = self(L);
  size_t i = check_index(L, 2, b);
  const auto& info = gl::elem_info(b.type());
  uint32_t v[4];
  to_components(L, 3, info, v, "buffer:set value");
  b.upload(v, i * info.components, info.components);
  return 0;
}

// buf:upload(table [, first]) writes elements starting at element `first` (default 1).
int w_upload(lua_State* L) {
  Buffer& b = self(L);
  if (!lua_istable(L, 2)) throw Error("buffer:upload: table expected, got " + type_name_at(L, 2));
  size_t first = lua_isnoneornil(L, 3) ? 0 : check_index(L, 3, b);
  const auto& info = gl::elem_info(b.type());
  auto data = table_to_components(L, 2, info, "buffer:upload");
  if (first * info.components + data.size() > b.components())
    throw Error("buffer:upload: " + std::to_string(data.size() / info.components) + " elements from index " +
                std::to_string(first + 1) + " overrun the buffer's " + std::to_string(b.count()));
  b.upload(data.data(), first * info.components, data.size());
  return 0;
}

// buf:download([first, count]) -> table of elements
int w_download(lua_State* L) {
  Buffer& b = self(L);
  size_t first = lua_isnoneornil(L, 2) ? 0 : check_index(L, 2, b);
  long long count = lua_isnoneornil(L, 3) ? (long long)(b.count() - first) : check_integer(L, 3, "count");
  if (count < 0 || first + size_t(count) > b.count())
    throw Error("buffer:download: " + std::to_string(count) + " elements from index " + std::to_string(first + 1) +
                " overrun the buffer's " + std::to_string(b.count()));
  const auto& info = gl::elem_info(b.type());
  std::vector<uint32_t> data(size_t(count) * info.components);
  if (count > 0) b.download(data.data(), first * info.components, data.size());
  lua_createtable(L, int(count), 0);
  for (long long i = 0; i < count; ++i) {
    push_components(L, info, &data[size_t(i) * info.components]);
    lua_rawseti(L, -2, int(i + 1));
  }
  return 1;
}

int w_fill(lua_State* L) {
  Buffer& b = self(L);
  double v = check_number(L, 2, "buffer:fill value");
  const auto& info = gl::elem_info(b.type());
  if (info.is_float) b.fill_float(float(v));
  else b.fill_uint(integer_component(v, info.is_signed, "buffer:fill value"));
  return 0;
}

// buf:pointer() -> lightuserdata to the mapped storage; the Lua side wraps it as an FFI cdata.
int w_pointer(lua_State* L) {
  lua_pushlightuserdata(L, self(L).map());
  return 1;
}

int w_tostring(lua_State* L) {
  auto* ud = static_cast<Box<Buffer>*>(test_type(L, 1, kType));
  if (!ud || !ud->ptr) lua_pushstring(L, "Buffer (released)");
  else lua_pushfstring(L, "Buffer(%s x %d)", gl::elem_info(ud->ptr->type()).name, int(ud->ptr->count()));
  return 1;
}

int w_len(lua_State* L) { return w_size(L); }

}  // namespace

void open_buffer(lua_State* L) {
  static const luaL_Reg methods[] = {
      SN_FN("size", w_size),         SN_FN("type", w_type), SN_FN("get", w_get),   SN_FN("set", w_set),
      SN_FN("upload", w_upload),     SN_FN("download", w_download), SN_FN("fill", w_fill),
      SN_FN("pointer", w_pointer),   {nullptr, nullptr}};
  static const luaL_Reg meta[] = {SN_FN("__len", w_len), {nullptr, nullptr}};
  define_box_type<Buffer>(L, kType, methods, wrap<w_tostring>, meta);
  lua_pushcfunction(L, wrap<w_new>);
  lua_setfield(L, -2, "buffer");
}

}  // namespace sn::lua
