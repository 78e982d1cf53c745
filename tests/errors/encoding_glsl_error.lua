-- expect: encoding_glsl_error\.lua:5: sn\.encoding\.define: encoding 'warp': its GLSL does not compile
-- expect: encoding_glsl_error\.lua:5 encoding warp:2: error: no function with name 'sine'
local sn = require "shadenet"
-- The error names the defining line, then the line within the GLSL text.
sn.encoding.define { name = "warp", outputs = 1, glsl = "float a = x[0];\nreturn sine(a);",
                     lua = function(x) return { math.sin(x[1]) } end }
