-- The built-in `frequency` encoding (NeRF's positional encoding) written as a user's definition,
-- `lua_frequency`: the same GLSL, word for word, and a Lua twin of it. A template for an encoding
-- of your own (docs/lua-api/networks.md, "Your own encoding"); tests/lua/test_encoding_define.lua
-- checks that it encodes, trains and renders exactly as the built-in, and
-- bench/encoding_twin.lua measures what its Lua twin costs.
--   build/shadenet examples/lua_frequency.lua      prints both encodings of one uv
local sn = require "shadenet"

local PI = math.pi
sn.encoding.define {
  name = "lua_frequency",
  count = { "bands", min = 1, max = 16, default = 6 },
  include_input = true,
  outputs = function(w, n, keep) return (keep and w or 0) + 2 * n * w end,
  glsl = [[if (keep) { if (j < w) return x[j]; j -= w; }
  int c = j / (2 * n), k = (j / 2) % n;
  float t = x[c] * float(1 << k);
  // t = r + u with r an integer, |u| <= 1/2 (exact in float): sin(pi t) = (-1)^r sin(pi u),
  // cos(pi t) = (-1)^r sin(pi (1/2 - |u|)), so their zeros are exact (pi is not a float:
  // sin(pi * 1.0) was 8.7e-8, which training on a zero input made a weight change).
  float r = floor(t + 0.5), u = t - r;
  float sign = mod(r, 2.0) == 0.0 ? 1.0 : -1.0;
  return sign * sin(SN_ENC_PI * ((j & 1) == 0 ? u : 0.5 - abs(u)));]],
  lua = function(x, n, keep)
    local out = {}
    if keep then for c = 1, #x do out[#out + 1] = x[c] end end
    for c = 1, #x do
      for k = 0, n - 1 do
        local t = PI * (x[c] * 2 ^ k)
        out[#out + 1], out[#out + 2] = math.sin(t), math.cos(t)
      end
    end
    return out
  end,
}

if arg and arg[0] and arg[0]:match("lua_frequency%.lua$") then
  for _, kind in ipairs { "frequency", "lua_frequency" } do
    local net = sn.mlp { inputs = { "uv" }, hidden = { 8 }, encoding = { uv = { kind, bands = 2 } } }
    local e = net:encode { 0.25, 0.5 }
    print(("%-13s %s"):format(kind, table.concat((function()
      local t = {}
      for i, v in ipairs(e) do t[i] = ("%.3f"):format(v) end
      return t
    end)(), " ")))
  end
end
