-- SHADENET_GL_DEBUG=1 prints the driver's debug messages to stderr inside the call that caused
-- them (a GL error made through the FFI here), =all adds notifications, 0 or unset prints none,
-- and any other value is an error naming the valid ones. A whole train and render under it
-- raises no GL error.
local C = require "script_check"

local child, base = C.child("gl_debug", [[
local sn = require "shadenet"
local ffi = require "ffi"
ffi.cdef [=[
typedef void (*sn_test_bind_buffer)(unsigned target, unsigned buffer);
extern sn_test_bind_buffer epoxy_glBindBuffer;
]=]
sn.gl_info()
if arg[1] == "error" then
  ffi.C.epoxy_glBindBuffer(0x90D2, 4242)  -- GL_SHADER_STORAGE_BUFFER and a name never generated
else
  local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 48, 36 }, views = { count = 2, elevation = 20 } }
  local data = scene:dataset { inputs = { "normal", "view" }, target = sn.lighting.phong {}, seed = 3 }
  local net = sn.mlp { inputs = 6, hidden = { 6, 6 }, seed = 5 }
  sn.train { nets = { net }, data = data, epochs = 1, batch = 8, backend = "gl" }
  scene:render(net, { backend = "gl" })
end
io.stderr:write("after the call\n")
]])

local function run(setting, what) return C.run(child, { what }, setting and { SHADENET_GL_DEBUG = setting } or nil) end

for _, setting in ipairs { "1", "all" } do
  local code, out = run(setting, "error")
  assert(code == 0, out)
  local message = out:find("GL debug %(high, error, id %d+%): [^\n]*GL_INVALID_OPERATION")
  assert(message and message < out:find("after the call", 1, true), setting .. ": the message, inside the call:\n" .. out)
end
local code, out
for _, setting in ipairs { false, "0", "" } do
  code, out = run(setting or nil, "error")
  assert(code == 0 and not out:find("GL debug", 1, true), tostring(setting) .. ":\n" .. out)
end
code, out = run("1", "pipeline")
assert(code == 0 and not out:find("GL debug (high, error", 1, true), "training and rendering raise no GL error:\n" .. out)
code, out = run("verbose", "error")
assert(code ~= 0 and out:find("SHADENET_GL_DEBUG='verbose': unknown setting (valid: 0, 1, all)", 1, true), out)
C.rm(base)
print("ok")
