-- The input encodings written again in Lua, in double precision, from their definitions in
-- docs/lua-api/networks.md (not from runtime/nn/encoding_builtin.cpp): what a network's first
-- layer should read. oneblob's bin masses are integrated numerically (Simpson's rule), sh's
-- polynomials carry their constants as square roots.
local M = {}

local pi = math.pi

-- The raw width of an input by name: G-buffer attributes 3 (uv 2), anything else 1.
local attribute = { normal = 3, view = 3, position = 3, world_position = 3, uv = 2, base_color = 3, tangent = 3,
                    bitangent = 3 }
function M.width(name) return attribute[name] or 1 end

-- The standard normal density integrated over [a, b] (Simpson, 200 intervals: error ~1e-13).
local function gauss_mass(a, b)
  local n, h = 200, (b - a) / 200
  local function phi(t) return math.exp(-0.5 * t * t) / math.sqrt(2 * pi) end
  local s = phi(a) + phi(b)
  for i = 1, n - 1 do s = s + (i % 2 == 1 and 4 or 2) * phi(a + i * h) end
  return s * h / 3
end

local function sh(x, y, z, degree)
  local r = 1 / math.sqrt(pi)
  local t = {
    r / 2,
    -math.sqrt(3) * y * r / 2, math.sqrt(3) * z * r / 2, -math.sqrt(3) * x * r / 2,
    math.sqrt(15) * x * y * r / 2, -math.sqrt(15) * y * z * r / 2, math.sqrt(5) * (3 * z * z - 1) * r / 4,
    -math.sqrt(15) * x * z * r / 2, math.sqrt(15) * (x * x - y * y) * r / 4,
    math.sqrt(70) * y * (-3 * x * x + y * y) * r / 8, math.sqrt(105) * x * y * z * r / 2,
    math.sqrt(42) * y * (1 - 5 * z * z) * r / 8, math.sqrt(7) * z * (5 * z * z - 3) * r / 4,
    math.sqrt(42) * x * (1 - 5 * z * z) * r / 8, math.sqrt(105) * z * (x * x - y * y) * r / 4,
    math.sqrt(70) * x * (-x * x + 3 * y * y) * r / 8,
  }
  local out = {}
  for j = 1, degree * degree do out[j] = t[j] end
  return out
end

-- References of encodings a test defines with sn.encoding.define: name -> function(e, x).
M.user = {}

-- One input group's components x (a list) under encoding e = { name, bands/bins/degree,
-- include_input, range } (net:spec().encoding[input]).
function M.encode_group(e, x)
  local kind, out = e[1], {}
  local function put(v) out[#out + 1] = v end
  if (kind == "frequency" or kind == "triangle_wave") and e.include_input then
    for _, v in ipairs(x) do put(v) end
  end
  if kind == "identity" then
    for _, v in ipairs(x) do put(v) end
  elseif kind == "frequency" then
    for _, v in ipairs(x) do
      for k = 0, e.bands - 1 do
        put(math.sin(2 ^ k * pi * v))
        put(math.cos(2 ^ k * pi * v))
      end
    end
  elseif kind == "triangle_wave" then
    for _, v in ipairs(x) do
      for k = 0, e.bands - 1 do
        local u = 2 ^ (k - 1) * v + k / 4
        put(4 * math.abs(u - math.floor(u) - 0.5) - 1)
      end
    end
  elseif kind == "oneblob" then
    local n, lo, hi = e.bins, e.range[1], e.range[2]
    for _, v in ipairs(x) do
      local s = (v - lo) / (hi - lo)
      -- bin i covers [i/n, (i+1)/n]; the Gaussian has sigma 1/n: in units of sigma, [i - ns, i + 1 - ns]
      for i = 0, n - 1 do put(gauss_mass(i - n * s, i + 1 - n * s)) end
    end
  elseif kind == "sh" then
    assert(#x == 3, "sh needs 3 components")
    for _, v in ipairs(sh(x[1], x[2], x[3], e.degree)) do put(v) end
  elseif M.user[kind] then
    for _, v in ipairs(M.user[kind](e, x)) do put(v) end
  else
    error("encoding_reference: no reference for encoding " .. tostring(kind))
  end
  return out
end

-- A raw input row of `net` (its inputs in net:inputs() order) as its first layer reads it.
function M.encode(net, x)
  local enc, out, at = net:spec().encoding, {}, 0
  for _, name in ipairs(net:inputs()) do
    local w, group = M.width(name), {}
    for c = 1, w do group[c] = x[at + c] end
    at = at + w
    local e = enc[name]
    for _, v in ipairs(e and M.encode_group(e, group) or group) do out[#out + 1] = v end
  end
  assert(at == #x, ("encoding_reference: the inputs take %d numbers, the row has %d"):format(at, #x))
  return out
end

return M
