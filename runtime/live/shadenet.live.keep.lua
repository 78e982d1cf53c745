-- sn.keep: values made once and kept across reloads (a trained network), with the snapshots
-- that let every re-run start from the kept weights.
local sn = require "shadenet.core"
local S = require "shadenet.live.state"
local live = sn.live

local keep = {}

-- Networks (and tables holding them) are snapshotted when made; every re-run starts from the
-- snapshot, so the script's edits apply to the trained weights and deleting an edit undoes it.
live.restorers = {
  -- The weights and biases in the shared flat layout, and the values its condition inputs render
  -- with (net:set_input); counters stay as they are.
  Mlp = {
    snapshot = function(net)
      local inputs = {}
      for _, c in ipairs(net:conditions()) do inputs[c.name] = c.value end
      return { params = net:params(), inputs = inputs }
    end,
    restore = function(net, state)
      net:set_params(state.params)
      -- A value outside a range a later training moved the input to stays as that training left it.
      for name, v in pairs(state.inputs) do pcall(net.set_input, net, name, v) end
    end,
  },
}

local function type_of(v)
  local mt = getmetatable(v)
  if type(v) ~= "userdata" or not mt then return nil end
  for name, r in pairs(live.restorers) do
    if debug.getregistry()[name] == mt then return name, r end
  end
  return nil
end

-- Whether v is a value the restorers know (a network).
function keep.restorable(v) return (type_of(v)) ~= nil end

function keep.snapshot(v, seen)
  seen = seen or {}
  local _, r = type_of(v)
  if r then return { value = v, state = r.snapshot(v) } end
  if type(v) == "table" and not seen[v] then
    seen[v] = true
    local parts = {}
    for _, x in pairs(v) do
      local s = keep.snapshot(x, seen)
      if s then
        if s.value then parts[#parts + 1] = s else for _, p in ipairs(s) do parts[#parts + 1] = p end end
      end
    end
    if #parts > 0 then return parts end
  end
  return nil
end

function keep.restore(snap)
  if not snap then return end
  if snap.value then
    local _, r = type_of(snap.value)
    r.restore(snap.value, snap.state)
  else
    for _, s in ipairs(snap) do keep.restore(s) end
  end
end

-- Keys compare by value (numbers, strings, booleans, nested tables of them).
local function same_key(a, b)
  if type(a) ~= type(b) then return false end
  if type(a) ~= "table" then return a == b end
  for k, v in pairs(a) do if not same_key(v, b[k]) then return false end end
  for k in pairs(b) do if a[k] == nil then return false end end
  return true
end

-- sn.keep(name, make [, key]) -> the value make() returned the first time. A different `key`
-- (e.g. the training settings) makes it again; sn.forget(name) too.
function sn.keep(name, make, key)
  if type(name) ~= "string" then error("sn.keep: the first argument must be a name (a string), got " .. type(name), 2) end
  if type(make) ~= "function" then
    error(("sn.keep('%s', make): make must be a function that builds the value, got %s"):format(name, type(make)), 2)
  end
  local k = S.kept[name]
  if k and (key == nil or same_key(key, k.key)) then return k.value end
  local value = make()
  if value == nil then error(("sn.keep('%s'): the function returned nil; it must return the value to keep"):format(name), 2) end
  S.kept[name] = { value = value, key = key, snapshot = keep.snapshot(value) }
  return value
end

-- sn.forget(name): the next sn.keep(name, ...) makes the value again (nil: forget all).
function sn.forget(name)
  if name == nil then S.kept = {} return end
  if S.kept[name] == nil then
    local names = sn.kept()
    error(("sn.forget: nothing kept under '%s' (kept: %s)"):format(tostring(name),
      #names > 0 and table.concat(names, ", ") or "none"), 2)
  end
  S.kept[name] = nil
end

-- sn.kept() -> sorted names of the kept values
function sn.kept()
  local names = {}
  for n in pairs(S.kept) do names[#names + 1] = n end
  table.sort(names)
  return names
end

return keep
