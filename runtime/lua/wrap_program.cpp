// sn.program{...} and program:dispatch{...}: compute and graphics programs from shaders/.
#include <epoxy/gl.h>

#include <cmath>
#include <cstdio>
#include <set>
#include <string>

#include "gl/buffer.h"
#include "gl/program.h"
#include "gl/render_target.h"
#include "lua/binding.h"
#include "lua/module.h"
#include "io/text.h"
#include "lua/program_bindings.h"

namespace sn::lua {

namespace {

constexpr const char* kType = "Program";
using gl::Program;

gl::Defines read_defines(lua_State* L, int idx) {
  gl::Defines d;
  if (lua_isnil(L, idx)) return d;
  if (!lua_istable(L, idx)) throw Error("sn.program option 'defines': table expected, got " + type_name_at(L, idx));
  lua_pushnil(L);
  while (lua_next(L, idx)) {
    if (lua_type(L, -2) != LUA_TSTRING) throw Error("sn.program 'defines': keys must be names");
    std::string k = lua_tostring(L, -2);
    std::string v;
    if (lua_type(L, -1) == LUA_TBOOLEAN) v = lua_toboolean(L, -1) ? "1" : "0";
    else if (lua_type(L, -1) == LUA_TNUMBER) {
      double x = lua_tonumber(L, -1);
      char buf[64];
      if (x == (long long)x) snprintf(buf, sizeof buf, "%lld", (long long)x);
      else snprintf(buf, sizeof buf, "%.9g", x);
      v = buf;
    } else if (lua_type(L, -1) == LUA_TSTRING) v = lua_tostring(L, -1);
    else throw Error("sn.program 'defines': " + k + " must be a number, string or boolean");
    d[k] = v;
    lua_pop(L, 1);
  }
  return d;
}

// sn.program{ compute = "file.comp" } or { vertex = "a.vert", fragment = "a.frag" }, defines = {...}
int w_new(lua_State* L) {
  Options o(L, 1, "sn.program", {"compute", "vertex", "fragment", "defines"});
  gl::ProgramDesc desc;
  desc.compute = o.string("compute", "");
  desc.vertex = o.string("vertex", "");
  desc.fragment = o.string("fragment", "");
  int d = o.push("defines");
  desc.defines = read_defines(L, d);
  lua_pop(L, 1);
  push(L, gl::get_program(desc), kType);
  return 1;
}

// prog:dispatch{ groups = {x,y,z} | n, buffers = {...}, uniforms = {...}, textures = {...} }
int w_dispatch(lua_State* L) {
  Program& p = check<Program>(L, 1, kType);
  Options o(L, 2, "program:dispatch", {"groups", "buffers", "uniforms", "textures"});
  auto g = o.numbers("groups");
  if (g.empty() || g.size() > 3) throw Error("program:dispatch option 'groups': 1 to 3 numbers expected");
  // Checked before the cast: 2^32 + 1 wrapped to 1 group, 1.9 ran 1, -1 read as 4294967295.
  unsigned count[3] = {1, 1, 1};
  for (std::size_t i = 0; i < g.size(); ++i) {
    GLint max = 0;
    glGetIntegeri_v(GL_MAX_COMPUTE_WORK_GROUP_COUNT, GLuint(i), &max);
    if (!(g[i] == std::floor(g[i]) && g[i] >= 1 && g[i] <= double(max)))
      throw Error(o.where("groups") + ": " + "xyz"[i] + " must be a whole number in 1.." + std::to_string(max) +
                  " (this driver's limit), got " + io::whole_text(g[i]));
    count[i] = unsigned(g[i]);
  }
  apply_bindings(L, o, p);
  gl::dispatch(p, count[0], count[1], count[2]);
  return 0;
}

int w_uniforms(lua_State* L) {
  auto names = check<Program>(L, 1, kType).uniform_names();
  push_strings(L, names);
  return 1;
}

int w_local_size(lua_State* L) {
  Program& p = check<Program>(L, 1, kType);
  for (int i = 0; i < 3; ++i) lua_pushinteger(L, p.local_size(i));
  return 3;
}

int w_tostring(lua_State* L) {
  auto* ud = static_cast<Box<Program>*>(test_type(L, 1, kType));
  if (!ud || !ud->ptr) lua_pushstring(L, "Program (released)");
  else lua_pushfstring(L, "Program(%s)", ud->ptr->name().c_str());
  return 1;
}

int w_cache_size(lua_State* L) {
  lua_pushinteger(L, lua_Integer(gl::program_cache_size()));
  return 1;
}

}  // namespace

namespace {
// Once per program and name: commenting out a uniform's use is an edit, not an error.
void warn_unused_uniform(const gl::Program& p, const std::string& name) {
  static std::set<std::pair<std::string, std::string>> said;
  if (said.insert({p.name(), name}).second)
    fprintf(stderr, "note: program %s declares uniform '%s' but does not use it (the compiler removed it); its value "
                    "is ignored\n", p.name().c_str(), name.c_str());
}
}  // namespace

void apply_bindings(lua_State* L, const Options& o, gl::Program& p) {
  // buffers: array part binds in order from binding 0; named entries bind to the SSBO block of that name.
  int bi = o.push("buffers");
  if (!lua_isnil(L, bi)) {
    if (!lua_istable(L, bi)) throw Error(o.where("buffers") + ": table expected");
    if (std::string shared = p.shared_storage_binding(); !shared.empty())
      throw Error(o.where("buffers") + ": " + p.name() + ": " + shared + "; give each block its own binding");
    // Every block gets a buffer of this call, and every buffer a block: a block left out read
    // whatever an earlier dispatch had bound there, and an extra buffer was dropped.
    const auto& blocks = p.storage_blocks();
    auto block_list = [&] {
      std::string s;
      for (const auto& b : blocks) s += (s.empty() ? "" : ", ") + b.name + " at " + std::to_string(b.binding);
      return s.empty() ? std::string("none") : s;
    };
    std::set<GLuint> bound;
    lua_pushnil(L);
    while (lua_next(L, bi)) {
      auto& buf = check<gl::Buffer>(L, -1, "Buffer");
      GLuint binding;
      const int key = lua_type(L, -2);
      if (key != LUA_TNUMBER && key != LUA_TSTRING)
        throw Error(o.where("buffers") + ": the key " + luaL_typename(L, -2) +
                    " is neither a position (buffers[1] binds binding 0) nor a buffer block's name");
      if (key == LUA_TNUMBER) {
        const double k = lua_tonumber(L, -2);
        if (!(k == std::floor(k) && k >= 1 && k <= 65536))
          throw Error(o.where("buffers") + ": the key [" + io::number_text(k) +
                      "] is not a position 1, 2, ... (buffers[1] binds binding 0)");
        binding = GLuint(k - 1);
        bool found = false;
        for (const auto& b : blocks) found = found || GLuint(b.binding) == binding;
        if (!found)
          throw Error(o.where("buffers") + ": buffer " + io::number_text(lua_tonumber(L, -2)) + " binds binding " +
                      std::to_string(binding) + ", where " + p.name() + " has no buffer block (its blocks and bindings: " +
                      block_list() + ")");
      } else {
        std::string name = lua_tostring(L, -2);
        GLuint index = glGetProgramResourceIndex(p.id(), GL_SHADER_STORAGE_BLOCK, name.c_str());
        if (index == GL_INVALID_INDEX) throw Error(o.where("buffers") + ": program has no buffer block '" + name + "'");
        const GLenum prop = GL_BUFFER_BINDING;
        GLint b = 0;
        glGetProgramResourceiv(p.id(), GL_SHADER_STORAGE_BLOCK, index, 1, &prop, 1, nullptr, &b);
        binding = GLuint(b);
      }
      glBindBufferBase(GL_SHADER_STORAGE_BUFFER, binding, buf.id());
      bound.insert(binding);
      lua_pop(L, 1);
    }
    for (const auto& b : blocks)
      if (!bound.count(GLuint(b.binding)))
        throw Error(o.where("buffers") + ": " + p.name() + "'s buffer block '" + b.name + "' (binding " +
                    std::to_string(b.binding) + ") has no buffer: give it one, as buffers[" + std::to_string(b.binding + 1) +
                    "] or buffers." + b.name);
  }
  lua_pop(L, 1);

  int ui = o.push("uniforms");
  if (!lua_isnil(L, ui)) {
    if (!lua_istable(L, ui)) throw Error(o.where("uniforms") + ": table expected");
    lua_pushnil(L);
    while (lua_next(L, ui)) {
      if (lua_type(L, -2) != LUA_TSTRING) throw Error(o.where("uniforms") + ": keys must be uniform names");
      std::string name = lua_tostring(L, -2);
      auto v = lua_type(L, -1) == LUA_TBOOLEAN ? std::vector<double>{double(lua_toboolean(L, -1))}
                                               : check_numbers(L, -1, ("uniform '" + name + "'").c_str());
      if (!p.set_uniform(name, v)) warn_unused_uniform(p, name);
      lua_pop(L, 1);
    }
  }
  lua_pop(L, 1);

  // textures = { u_name = target } (attachment 1) or { u_name = {target, i} }
  int ti = o.push("textures");
  if (!lua_isnil(L, ti)) {
    if (!lua_istable(L, ti)) throw Error(o.where("textures") + ": table expected");
    int unit = 0;
    lua_pushnil(L);
    while (lua_next(L, ti)) {
      if (lua_type(L, -2) != LUA_TSTRING) throw Error(o.where("textures") + ": keys must be sampler names");
      std::string name = lua_tostring(L, -2);
      int attachment = 0;
      if (lua_istable(L, -1)) {
        lua_rawgeti(L, -1, 2);
        attachment = lua_isnil(L, -1) ? 0 : check_int32(L, -1, "texture attachment") - 1;
        lua_pop(L, 1);
        lua_rawgeti(L, -1, 1);
        lua_replace(L, -2);
      }
      auto& t = check<gl::RenderTarget>(L, -1, "Target");
      if (attachment < 0 || attachment >= t.attachments())
        throw Error("texture '" + name + "': attachment " + std::to_string(attachment + 1) + " out of range 1.." +
                    std::to_string(t.attachments()));
      glBindTextureUnit(GLuint(unit), t.color_texture(attachment));
      p.set_uniform(name, {double(unit)});
      ++unit;
      lua_pop(L, 1);
    }
  }
  lua_pop(L, 1);
}

void open_program(lua_State* L) {
  static const luaL_Reg methods[] = {SN_FN("dispatch", w_dispatch), SN_FN("uniforms", w_uniforms),
                                     SN_FN("local_size", w_local_size), {nullptr, nullptr}};
  define_box_type<Program>(L, kType, methods, wrap<w_tostring>);
  lua_pushcfunction(L, wrap<w_new>);
  lua_setfield(L, -2, "program");
  lua_pushcfunction(L, wrap<w_cache_size>);
  lua_setfield(L, -2, "program_cache_size");
}

}  // namespace sn::lua
