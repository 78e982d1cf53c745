-- expect: activation_bad_name\.lua:4: sn\.activation\.define: activation name 'my act': use lower-case letters, digits and _ \(at most 40\)
-- The name's rules are checked before the GLSL is compiled under that name (a GLSL syntax error).
local sn = require "shadenet"
sn.activation.define { name = "my act", glsl = "x", grad = "vec4(1.0)", lua = function(x) return x end, lua_grad = function() return 1 end }
