-- expect: dataset_export_unwritable\.lua:6: dataset:export: cannot write dataset '.*/cloth\.inputs\.npy': cannot create folder '.*': Not a directory
local sn = require "shadenet"
local blocker = sn.fs.write(sn.fs.tempdir("error") .. "/blocker", "")  -- a file: nothing can be written below it
local data = sn.dataset { x = { { 0, 0, 1 }, { 0, 1, 0 } }, y = { { 1, 0, 0 }, { 0, 1, 0 } } }
local ok, err = pcall(function()
  local path = data:export(blocker .. "/out/cloth.json") return path end)
error(err, 0)
