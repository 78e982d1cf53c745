-- expect: activation_lanes_mixed\.lua:6: sn\.activation\.define: activation 'swapped': its glsl \(GLSL\) gives .* at -3\.9863, its Lua twin -3\.9863: lane x of the vec4 holds lane y's value, and each lane is a unit of its own
-- A vec4 holds four units: GLSL that swaps its lanes agrees with the twin only where all four
-- lanes hold one value, and would train and render on gl as another function.
local sn = require "shadenet"
local same, one = function(x) return x end, function() return 1 end
sn.activation.define { name = "swapped", glsl = "x.yxwz", grad = "vec4(1.0)", lua = same, lua_grad = one }
