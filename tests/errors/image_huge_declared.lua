-- expect: image_huge_declared\.lua:5: image file 'tests/data/huge_declared\.png': 30000x30000 is 900000000 pixels, above the limit of 268435456 \(sn\.limits\{ image_pixels = \.\.\. \} raises it\)
local sn = require "shadenet"

-- A 74-byte PNG declaring 30000 x 30000 pixels: refused before 10 GB are asked for.
sn.image.load("tests/data/huge_declared.png")
