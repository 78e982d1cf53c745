// Compute dispatch end to end: a shader's output equals the same computation in C++.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "gl/buffer.h"
#include "gl/buffer_texture.h"
#include "gl/context.h"
#include "gl/program.h"
#include "gl/render_target.h"

#include <epoxy/gl.h>

using namespace sn::gl;

TEST(Compute, ShaderMatchesCpp) {
  current();
  const int n = 10000;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> u(-3.f, 3.f);
  std::vector<float> x(n);
  for (float& v : x) v = u(rng);
  Buffer in(ElemType::float32, n), out(ElemType::float32, n);
  in.upload(x.data(), 0, n);
  auto p = get_program({.compute = "tests/data/shaders/poly.comp", .defines = {{"LOCAL_SIZE", "64"}}});
  p->set_uniform("u_count", {double(n)});
  p->set_uniform("u_scale", {0.5});
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
  dispatch(*p, (n + 63) / 64);
  auto y = out.download_floats();
  for (int i = 0; i < n; ++i) {
    double xd = x[i];
    double expect = 0.5 * (xd * xd * xd - 2.0 * xd) + std::tanh(xd);
    ASSERT_NEAR(y[i], expect, 2e-5 * std::max(1.0, std::abs(expect))) << "at " << i << " x=" << xd;
  }
}

// A dispatch the driver refuses (here: its program object deleted behind the Program's back)
// left the outputs as they were; it is an error naming the program and the GL error.
TEST(Compute, RefusedDispatchIsAnError) {
  current();
  auto p = get_program({.compute = "tests/data/shaders/poly.comp", .defines = {{"LOCAL_SIZE", "32"}}});
  glDeleteProgram(p->id());
  try {
    dispatch(*p, 1);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("dispatching " + p->name() + " (1x1x1 workgroups) failed: GL_INVALID_VALUE (0x501)"), std::string::npos) << m;
  }
  clear_program_cache();
  EXPECT_EQ(take_gl_errors(), 0u) << "the failed dispatch's errors were taken";
  EXPECT_EQ(gl_error_text(0x9999), "0x9999");

  // A call that failed before a dispatch (here a binding past the last one) is not dropped...
  auto q = get_program({.compute = "tests/data/shaders/poly.comp", .defines = {{"LOCAL_SIZE", "32"}}});
  Buffer b(ElemType::float32, 32);
  GLint bindings = 0;
  glGetIntegerv(GL_MAX_SHADER_STORAGE_BUFFER_BINDINGS, &bindings);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(bindings), b.id());
  try {
    dispatch(*q, 1);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("a GL call before dispatching " + q->name() + " failed: GL_INVALID_VALUE (0x501)"), std::string::npos)
        << m;
  }
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(bindings), b.id());  // nor blamed on an allocation
  EXPECT_THROW(
      {
        try {
          Buffer c(ElemType::float32, 4);
        } catch (const std::runtime_error& e) {
          EXPECT_STREQ(e.what(), "a GL call before creating a buffer failed: GL_INVALID_VALUE (0x501) "
                                 "(SHADENET_GL_DEBUG=1 prints the driver's reason)");
          throw;
        }
      },
      std::runtime_error);
  EXPECT_EQ(take_gl_errors(), 0u);
  Buffer c(ElemType::float32, 4);  // and then gone
}

TEST(Compute, ProgramCacheReusesEqualSources) {
  current();
  auto a = get_program({.compute = "tests/data/shaders/poly.comp", .defines = {{"LOCAL_SIZE", "64"}}});
  auto b = get_program({.compute = "tests/data/shaders/poly.comp", .defines = {{"LOCAL_SIZE", "64"}}});
  auto c = get_program({.compute = "tests/data/shaders/poly.comp", .defines = {{"LOCAL_SIZE", "32"}}});
  EXPECT_EQ(a.get(), b.get());
  EXPECT_NE(a.get(), c.get());
  EXPECT_EQ(c->local_size(0), 32);
  // A request that is neither a compute nor a vertex + fragment program is refused, cached
  // source or not (a cached compute program answered for {compute, vertex}).
  for (ProgramDesc bad : {ProgramDesc{.compute = "tests/data/shaders/poly.comp", .vertex = "mesh.vert"},
                          ProgramDesc{.compute = "tests/data/shaders/poly.comp", .fragment = "missing.frag"},
                          ProgramDesc{.vertex = "mesh.vert"}}) {
    bad.defines = {{"LOCAL_SIZE", "64"}};
    try {
      get_program(bad);
      ADD_FAILURE() << bad.vertex << bad.fragment;
    } catch (const std::invalid_argument& e) {
      EXPECT_STREQ(e.what(), "a program takes either 'compute' or 'vertex' + 'fragment'");
    }
  }
}

TEST(Buffer, UploadDownloadFillAndRange) {
  current();
  Buffer b(ElemType::vec4, 3);
  EXPECT_EQ(b.components(), 12u);
  float v[4] = {1, 2, 3, 4};
  b.upload(v, 4, 4);
  auto all = b.download_floats();
  EXPECT_EQ(all[0], 0.f);
  EXPECT_EQ(all[5], 2.f);
  b.fill_float(0.25f);
  EXPECT_EQ(b.download_floats()[11], 0.25f);
  EXPECT_THROW(b.upload(v, 10, 4), std::out_of_range);
  EXPECT_THROW(parse_elem_type("half"), std::invalid_argument);
}

// A range of one buffer into another, on the device, what a shader wrote before it included
// (the gl trainer commits a dispatch's staged parameters so); ranges outside either are refused.
TEST(Buffer, CopyFromTakesARangeAfterShaderWrites) {
  current();
  auto p = get_program({.compute = "tests/data/shaders/poly.comp", .defines = {{"LOCAL_SIZE", "32"}}});
  Buffer x(ElemType::float32, 64), y(ElemType::float32, 64), z(ElemType::float32, 16);
  std::vector<float> xs(64);
  for (int i = 0; i < 64; ++i) xs[std::size_t(i)] = 0.01f * float(i);
  x.upload(xs.data(), 0, xs.size());
  z.fill_float(-1.f);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, x.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, y.id());
  p->set_uniform("u_count", {64.0});
  p->set_uniform("u_scale", {0.5});
  dispatch_without_barrier(*p, 2);  // no barrier: copy_from must order the copy after the writes
  z.copy_from(y, 40, 4, 8);
  const std::vector<float> ys = y.download_floats(), zs = z.download_floats();
  for (int i = 0; i < 16; ++i)
    EXPECT_EQ(zs[std::size_t(i)], i >= 4 && i < 12 ? ys[std::size_t(36 + i)] : -1.f) << i;
  EXPECT_NE(zs[4], 0.f);
  EXPECT_THROW(z.copy_from(y, 60, 0, 8), std::out_of_range);
  EXPECT_THROW(z.copy_from(y, 0, 12, 8), std::out_of_range);
}

// The pool hands out only buffers nobody holds, the smallest idle one that is large enough and
// of the type asked for, and keeps what was written to it.
TEST(Buffer, PooledBuffersAreReusedOnlyWhenIdle) {
  current();
  clear_buffer_pool();
  auto a = pooled_buffer(ElemType::vec4, 100);
  auto b = pooled_buffer(ElemType::vec4, 50);
  EXPECT_NE(a.get(), b.get());  // a is held
  EXPECT_GE(a->count(), 100u);
  const float v[4] = {7, 8, 9, 10};
  b->upload(v, 0, 4);
  Buffer* small = b.get();
  b.reset();
  EXPECT_NE(pooled_buffer(ElemType::uint32, 10).get(), small);  // another type
  auto c = pooled_buffer(ElemType::vec4, 40);
  EXPECT_EQ(c.get(), small);
  EXPECT_EQ(c->download_floats()[2], 9.f);  // not cleared
  auto d = pooled_buffer(ElemType::vec4, 60);  // c is held, a too: a new one
  EXPECT_NE(d.get(), a.get());
  EXPECT_NE(d.get(), c.get());
  a.reset();
  c.reset();
  EXPECT_EQ(pooled_buffer(ElemType::vec4, 45).get(), small);  // the smallest that is large enough
  clear_buffer_pool();
}

// The render target pool keeps a small idle target for the next view or frame, but not a large
// one: two idle 4096x4096 renders' targets held 1 GB for the rest of the process.
TEST(RenderTarget, OnlySmallTargetsArePooled) {
  current();
  clear_target_pool();
  std::weak_ptr<RenderTarget> small = pooled_target(640, 480, 2);
  EXPECT_FALSE(small.expired());  // idle, kept
  RenderTarget* again = pooled_target(640, 480, 2).get();
  EXPECT_EQ(again, small.lock().get());
  std::weak_ptr<RenderTarget> large = pooled_target(2048, 1100, 4);  // 144 MB of colour
  EXPECT_TRUE(large.expired());
  clear_target_pool();
  EXPECT_TRUE(small.expired());
}

// y of poly.comp with u_scale = 1, in double.
double poly(double x) { return x * x * x - 2 * x + std::tanh(x); }

GLint storage_flags(const Buffer& b) {
  GLint f = 0;
  glGetNamedBufferParameteriv(b.id(), GL_BUFFER_STORAGE_FLAGS, &f);
  return f;
}

// Storage is mappable only once a buffer is mapped (a driver may keep mappable storage in host
// memory); mapping keeps what uploads and shaders wrote, and what comes after lands in the new
// storage, read by shaders through a binding or a buffer texture.
TEST(Buffer, MappingMovesTheContentsIntoMappableStorage) {
  current();
  const int n = 64;
  Buffer in(ElemType::float32, n), out(ElemType::float32, n);
  EXPECT_EQ(storage_flags(in) & (GL_MAP_PERSISTENT_BIT | GL_MAP_READ_BIT | GL_MAP_WRITE_BIT), 0);
  std::vector<float> x(n);
  for (int i = 0; i < n; ++i) x[i] = 0.05f * float(i) - 1.0f;
  in.upload(x.data(), 0, n);
  auto run = [&](Program& prog) {
    prog.set_uniform("u_count", {double(n)});
    prog.set_uniform("u_scale", {1.0});
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
    dispatch(prog, 1);
  };
  auto prog = get_program({.compute = "tests/data/shaders/poly.comp", .defines = {{"LOCAL_SIZE", "64"}}});
  run(*prog);
  const unsigned before = out.id();
  const float* y = static_cast<const float*>(out.map());
  EXPECT_NE(out.id(), before);
  EXPECT_NE(storage_flags(out) & GL_MAP_PERSISTENT_BIT, 0);
  for (int i = 0; i < n; ++i) ASSERT_NEAR(y[i], poly(x[i]), 1e-5) << i;  // the shader's writes came along

  float* xp = static_cast<float*>(in.map());
  for (int i = 0; i < n; ++i) ASSERT_EQ(xp[i], x[i]) << i;  // so did the upload
  xp[3] = 1.5f;  // written through the new mapping, read by the next dispatch
  const float v = 0.25f;
  in.upload(&v, 7, 1);  // and through GL
  run(*prog);
  finish();
  EXPECT_NEAR(y[3], poly(1.5), 1e-5);
  EXPECT_NEAR(y[7], poly(0.25), 1e-5);

  BufferTexture tex(in);  // attached to the storage in place when bound
  Buffer fresh(ElemType::float32, n);
  BufferTexture late(fresh);
  fresh.upload(x.data(), 0, n);
  static_cast<float*>(fresh.map())[3] = 1.5f;  // mapped after the texture was made: bind() attaches the new storage
  auto from_texture = get_program(
      {.compute = "tests/data/shaders/poly.comp", .defines = {{"LOCAL_SIZE", "64"}, {"FROM_TEXTURE", "1"}}});
  for (const BufferTexture* t : {&tex, &late}) {
    out.fill_float(0);
    t->bind(0);
    run(*from_texture);
    finish();
    EXPECT_NEAR(y[5], poly(x[5]), 1e-5);
    EXPECT_NEAR(y[3], poly(1.5), 1e-5);
  }
}

TEST(Buffer, MappedPointerSeesShaderWrites) {
  current();
  Buffer in(ElemType::float32, 64), out(ElemType::float32, 64);
  float* p = static_cast<float*>(in.map());
  for (int i = 0; i < 64; ++i) p[i] = float(i);
  auto prog = get_program({.compute = "tests/data/shaders/poly.comp", .defines = {{"LOCAL_SIZE", "64"}}});
  prog->set_uniform("u_count", {64});
  prog->set_uniform("u_scale", {1.0});
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, in.id());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, out.id());
  dispatch(*prog, 1);
  float* q = static_cast<float*>(out.map());  // map() waits for the GPU
  EXPECT_NEAR(q[2], 2.0 * 2 * 2 - 4 + std::tanh(2.0), 1e-5);
}
