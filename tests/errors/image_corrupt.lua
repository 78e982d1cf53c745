-- expect: image_corrupt\.lua:4: image file 'tests/data/corrupt\.png'
local sn = require "shadenet"

sn.image.load("tests/data/corrupt.png")
