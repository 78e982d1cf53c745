-- expect: activation_twins_disagree\.lua:3: sn\.activation\.define: activation 'halfsine': its grad \(GLSL\) gives .* at -3\.9863, its Lua twin
local sn = require "shadenet"
sn.activation.define { name = "halfsine", glsl = "sin(x)", grad = "0.5 * cos(x)",
                       lua = math.sin, lua_grad = math.cos }
