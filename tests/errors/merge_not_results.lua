-- expect: merge\.lua: tests/errors/run\.json is missing: not a results folder
-- Merging a folder that holds no experiment's results says so.
arg = { [0] = "scripts/merge.lua", "tests/errors" }
dofile("scripts/merge.lua")
