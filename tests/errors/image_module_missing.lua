-- env: SHADENET_IMAGE_MODULE=/nonexistent/libshadenet_image.so
-- expect: image_module_missing\.lua:[0-9]+: cannot load the image module \(OpenImageIO\), needed to read, write or label images:
-- expect: /nonexistent/libshadenet_image\.so: no such file
-- expect: point SHADENET_IMAGE_MODULE at this build.s libshadenet_image\.so, or unset it
local sn = require "shadenet"

-- Everything but images works without the module; the first image saved needs it.
local img = sn.image.new { width = 4, height = 4, channels = 3 }
assert(sn.image.mse(img, img) == 0)
img:save("out/never_written.png")
