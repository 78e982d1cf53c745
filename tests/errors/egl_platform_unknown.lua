-- env: SHADENET_EGL_PLATFORM=gpu
-- expect: SHADENET_EGL_PLATFORM='gpu': unknown EGL platform \(valid: auto, device, surfaceless\)
-- expect: egl_platform_unknown\.lua:5: in main chunk
-- A typo in the EGL platform fails when the script first needs the GL context, naming the choices.
local sn = require "shadenet"
print("never runs", sn.gl_info().renderer)
