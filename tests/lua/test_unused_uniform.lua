-- A uniform the shader declares but no longer uses (its use commented out, as a live coder
-- does) is removed by the compiler; sn.draw and dispatch must take its value and ignore it (one
-- note on stderr), while a name the shader never declared is still an error listing the valid ones.
local sn = require "shadenet"

os.execute("mkdir -p out/tests/unused_uniform")
local path = "out/tests/unused_uniform/tint.frag"
local f = assert(io.open(path, "w"))
f:write([[
in vec3 v_world_normal;
uniform vec3 u_tint;
uniform float u_gain, u_bias[2];   // neither is used below any more
layout(location = 0) out vec4 o_color;
void main() {
  o_color = vec4(u_tint /* * u_gain + u_bias[0] */, 1.0);
}
]])
f:close()

local program = sn.program { vertex = "mesh.vert", fragment = path }
local sphere = sn.mesh.sphere { segments = 16, rings = 8 }
local target = sn.target { width = 32, height = 32 }
local camera = sn.camera { eye = { 0, 0, 3 } }
local ok, err = pcall(sn.draw, { target = target, program = program, mesh = sphere, camera = camera,
                                 clear = { 0, 0, 0, 0 },
                                 uniforms = { u_tint = { 0.25, 0.5, 0.75 }, u_gain = 2, u_bias = { 1, 2 } } })
assert(ok, "a declared but unused uniform must be accepted: " .. tostring(err))
local px = target:read():get(16, 16)
assert(math.abs(px[1] - 0.25) < 1e-6 and math.abs(px[2] - 0.5) < 1e-6 and math.abs(px[3] - 0.75) < 1e-6,
       ("the draw ran with u_tint: got %g %g %g"):format(px[1], px[2], px[3]))

-- A typo is still a typo.
ok, err = pcall(sn.draw, { target = target, program = program, mesh = sphere, camera = camera,
                           uniforms = { u_tnit = { 1, 1, 1 } } })
assert(not ok and err:find("has no uniform 'u_tnit'", 1, true) and err:find("u_tint", 1, true),
       "an undeclared uniform is an error naming the valid ones: " .. tostring(err))
print("unused uniform: u_gain and u_bias[2] accepted and ignored, u_tnit rejected")
