-- expect: image_volume\.lua:6: image file 'tests/data/volume\.dds': a volume image \(4x4x64\); shadenet reads 2-D images
local sn = require "shadenet"

-- A 4 KB DDS volume texture (4x4x64): OpenImageIO used to write 64 slices into a buffer sized
-- for one (a heap overflow).
sn.image.load("tests/data/volume.dds")
