-- expect: activation_compute_only\.lua:6: sn\.activation\.define: activation 'indexed': its glsl \(GLSL\) does not compile
-- expect: GLSL compile error in shaders/activation_check\.frag
-- expect: activation_compute_only\.lua:6 activation indexed \(glsl\):1: error: .gl_LocalInvocationIndex. undeclared
-- GLSL a compute shader accepts but a render's fragment shader does not: refused where defined.
local sn = require "shadenet"
sn.activation.define { name = "indexed", glsl = "x * float(gl_LocalInvocationIndex + 1u) / float(gl_LocalInvocationIndex + 1u)",
                       grad = "vec4(1.0)", lua = function(x) return x end, lua_grad = function() return 1 end }
