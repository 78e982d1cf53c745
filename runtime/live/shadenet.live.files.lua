-- Which files the script read, for live mode to watch: a package loader that records every Lua
-- module found on package.path, and dofile. The loop re-runs the script when one is saved.
local S = require "shadenet.live.state"

local function record_file(path)
  S.files[path] = true
end

local function file_loader(name)
  local path, err = package.searchpath(name, package.path)
  if not path then return err end
  S.modules[name] = path
  record_file(path)
  local chunk, msg = loadfile(path)
  if not chunk then
    error(("error loading module '%s' from file '%s':\n\t%s"):format(name, path, msg), 3)
  end
  return chunk
end

do  -- before Lua's own file searcher, after preload and the embedded modules
  local loaders = package.loaders
  local at = #loaders >= 2 and 3 or #loaders + 1
  table.insert(loaders, at, file_loader)
end

local plain_dofile = dofile
function dofile(path)  -- luacheck: ignore (the global, wrapped to record the file)
  if path then record_file(path) end
  return plain_dofile(path)
end
