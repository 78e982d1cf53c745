-- An activation that loops 10,000 times per call (the identity, slowly; no cpu code: the GLSL
-- loop does not translate), for the tests of llvmpipe's loop budget (65,535 iterations per
-- invocation): one layer of 4 units calls it once and fits; eight layers of 8 call it 16 times.
local sn = require "shadenet"
sn.activation.define {
  name = "slow_identity",
  glsl = "vec4 y = vec4(0.0); for (int i = 0; i < 10000; ++i) y = 0.5 * (y + x); return y;",
  grad = "vec4(1.0)",
  lua = function(x) return x end,
  lua_grad = function() return 1 end,
}
require("reference_forward").custom.slow_identity = function(z) return z end
return "slow_identity"
