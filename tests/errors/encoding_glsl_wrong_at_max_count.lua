-- expect: encoding_glsl_wrong_at_max_count\.lua:5: sn\.encoding\.define: encoding 'halfright': its GLSL gives 0 as output 9 of .* \(an input of 3 components, bands = 8\), its Lua twin
-- A GLSL that matches its twin at the default count alone is refused: it was checked there only,
-- and cpu (the twin) and gl (the GLSL) then trained different functions.
local sn = require "shadenet"
sn.encoding.define {
  name = "halfright", count = { "bands", min = 1, max = 8, default = 4 }, input_width = 3,
  outputs = function(w, n) return 2 * n end,
  glsl = "int k = j / 2; if (k >= 4) return 0.0; float t = float(k + 1) * (x[0] + x[1] + x[2]); "
         .. "return (j % 2) == 0 ? sin(t) : cos(t);",
  lua = function(x, n)
    local o = {}
    for k = 0, n - 1 do
      local t = (k + 1) * (x[1] + x[2] + x[3])
      o[#o + 1] = math.sin(t)
      o[#o + 1] = math.cos(t)
    end
    return o
  end }
