-- The scene the windowed test compares: a sphere's normal map, width x height from the
-- arguments. Run alone it writes the headless render: shadenet tests/window/render_scene.lua W H OUT.exr
local sn = require "shadenet"

local M = {}

function M.render(w, h)
  local target = sn.target { width = w, height = h }
  local sphere = sn.mesh.sphere { radius = 1, segments = 64, rings = 32 }
  local camera = sn.camera { eye = { 0.6, 0.8, 2.6 }, target = { 0, 0, 0 }, fov = 45 }
  local program = sn.program { vertex = "mesh.vert", fragment = "normals.frag" }
  sn.draw { target = target, program = program, mesh = sphere, camera = camera, clear = { 0, 0, 0, 0 } }
  return target
end

if arg and arg[0] and arg[0]:match("render_scene%.lua$") then
  local w, h, out = tonumber(arg[1]), tonumber(arg[2]), arg[3]
  M.render(w, h):read():save(out)
end
return M
