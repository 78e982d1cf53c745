-- OpenImageIO lives in a module loaded on first use (runtime/io/image_codec.h): a run that
-- never reads, writes or labels an image does not load it (it cost every start 0.15 s); the
-- first image saved loads it, and it stays out of the program's global symbol scope.
local sn = require "shadenet"

local mapped = require "mapped"

assert(not mapped("libOpenImageIO"), "OpenImageIO is loaded before any image was read or written")
assert(not mapped("libshadenet_image"), "the image module is loaded before any image was read or written")
local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 32, 24 }, views = { count = 1 } }
local truth = scene:render(sn.lighting.phong {}, { view = 1 })  -- images in memory need no module
assert(sn.image.mse(truth, truth) == 0)
assert(not mapped("libOpenImageIO"), "rendering and comparing images loaded OpenImageIO")
sn.fs.mkdir("out")
truth:save("out/image_module.png")
assert(mapped("libshadenet_image") and mapped("libOpenImageIO"), "saving an image loads the module")
local back = sn.image.load("out/image_module.png")
assert(back:size() == 32)
local w, h = sn.image.text_size("label", 16)
assert(w > 10 and h > 10)
print("ok")
