-- expect: image_missing\.lua:4: image file 'tests/data/no_such_image\.png' does not exist
local sn = require "shadenet"

sn.image.load("tests/data/no_such_image.png")
