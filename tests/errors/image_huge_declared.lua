-- expect: image_huge_declared\.lua:5: image file 'tests/data/huge_declared\.png': 30000x30000x3 is above the limit of 268435456 pixels and 64 channels \(io/image\.h\)
local sn = require "shadenet"

-- A 74-byte PNG declaring 30000 x 30000 pixels: refused before 10 GB are asked for.
sn.image.load("tests/data/huge_declared.png")
