-- Renders a real glTF model (the Khronos Duck) and a procedural sphere as normal maps:
-- world-space normals mapped to colours, background left transparent.
--   build/shadenet examples/render_normals.lua [mesh.gltf|.glb]
local sn = require "shadenet"

-- The Duck lives in ../shared/meshes beside the repository; look for it from the working
-- directory and from this script's folder, so the script runs from anywhere.
local function find(name)
  local script_dir = (arg and arg[0] or ""):match("^(.*)[/\\]") or "."
  local candidates = { "../shared/meshes/" .. name, script_dir .. "/../../shared/meshes/" .. name }
  if os.getenv("SHADENET_SHARED") then table.insert(candidates, 1, os.getenv("SHADENET_SHARED") .. "/meshes/" .. name) end
  for _, path in ipairs(candidates) do
    local f = io.open(path, "rb")
    if f then f:close() return path end
  end
  error("cannot find " .. name .. " (looked at " .. table.concat(candidates, ", ") .. ")")
end

-- A camera that frames the mesh's bounding sphere, seen from `azimuth` degrees around the
-- vertical axis and `elevation` degrees above the horizon.
local function framing_camera(mesh, azimuth, elevation, fov)
  local lo, hi = mesh:bounds()
  local center, radius = {}, 0
  for i = 1, 3 do
    center[i] = (lo[i] + hi[i]) / 2
    radius = radius + (hi[i] - lo[i]) ^ 2
  end
  radius = math.sqrt(radius) / 2
  local distance = radius / math.sin(math.rad(fov / 2))  -- the whole sphere fits the view
  local a, e = math.rad(azimuth), math.rad(elevation)
  local eye = { center[1] + distance * math.cos(e) * math.sin(a),
                center[2] + distance * math.sin(e),
                center[3] + distance * math.cos(e) * math.cos(a) }
  return sn.camera { eye = eye, target = center, fov = fov,
                     near = distance - radius * 1.01, far = distance + radius * 1.01 }
end

local normals = sn.program { vertex = "mesh.vert", fragment = "normals.frag" }  -- files under shaders/
local target = sn.target { width = 512, height = 512 }

local function render(mesh, camera, path)
  sn.draw { target = target, program = normals, mesh = mesh, camera = camera, clear = { 0, 0, 0, 0 } }
  print(target:read():save(path))
end

local duck = sn.mesh.load(arg[1] or find("Duck.gltf"))
print(duck)
render(duck, framing_camera(duck, 45, 20, 40), "out/duck_normals.png")

local sphere = sn.mesh.sphere { radius = 1, segments = 96, rings = 48 }
print(sphere)
render(sphere, framing_camera(sphere, 0, 0, 40), "out/sphere_normals.png")
