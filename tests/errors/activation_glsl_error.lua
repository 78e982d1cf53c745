-- expect: activation_glsl_error\.lua:4: sn\.activation\.define: activation 'wobble': its grad \(GLSL\) does not compile
-- expect: activation_glsl_error\.lua:4 activation wobble \(grad\):2: error
local sn = require "shadenet"
sn.activation.define { name = "wobble", glsl = "x + 0.1 * sin(x)", grad = "vec4 c = cos(x);\nreturn 1.0 + 0.1 * cosine(x);",
                       lua = function(x) return x + 0.1 * math.sin(x) end, lua_grad = function(x) return 1 + 0.1 * math.cos(x) end }
