-- sn.vec3: the few vector operations a lighting model's Lua twin needs, on {x, y, z} arrays, in
-- double precision, with the shaders' guards (normalize of a vector shorter than 1e-15 is zero,
-- as safe_normalize in shaders/include/lighting/common.glsl).
local sn = require "shadenet.core"

local sqrt = math.sqrt
local vec3 = {}

function vec3.dot(a, b) return a[1] * b[1] + a[2] * b[2] + a[3] * b[3] end
function vec3.cross(a, b)
  return { a[2] * b[3] - a[3] * b[2], a[3] * b[1] - a[1] * b[3], a[1] * b[2] - a[2] * b[1] }
end
function vec3.add(a, b) return { a[1] + b[1], a[2] + b[2], a[3] + b[3] } end
function vec3.sub(a, b) return { a[1] - b[1], a[2] - b[2], a[3] - b[3] } end
function vec3.scale(a, k) return { a[1] * k, a[2] * k, a[3] * k } end
function vec3.mul(a, b) return { a[1] * b[1], a[2] * b[2], a[3] * b[3] } end
function vec3.length(a) return sqrt(vec3.dot(a, a)) end
function vec3.normalize(a)
  local a2 = vec3.dot(a, a)
  if not (a2 >= 1e-30) then return { 0, 0, 0 } end
  local k = 1 / sqrt(a2)
  return { a[1] * k, a[2] * k, a[3] * k }
end
function vec3.clamp(x, lo, hi) return math.min(math.max(x, lo), hi) end

sn.vec3 = vec3
return vec3
