-- expect: activation_lua_nan\.lua:3: sn\.activation\.define: activation 'logish': lua\(-3\.9863\) returned -?nan
local sn = require "shadenet"
sn.activation.define { name = "logish", glsl = "log(x)", grad = "1.0 / x",
                       lua = function(x) return math.log(x) end, lua_grad = function(x) return 1 / x end }
