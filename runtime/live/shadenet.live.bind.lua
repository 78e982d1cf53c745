-- sn.live.bind: keys that step a value up and down without typing (a weight, a parameter of the
-- show's lighting model, a conditioning input of its network), shown in the window's corner.
-- The loop calls live._key for a key no built-in control uses; live._bind_lines for the HUD.
local sn = require "shadenet.core"
local S = require "shadenet.live.state"
local check = require "shadenet.live.check"
local view_of = require "shadenet.live.view"
local live = sn.live

local bind = {}

-- Keys the window already uses (input.cpp); a binding may take any other letter or digit.
local TAKEN = { ["1"] = true, ["2"] = true, ["3"] = true, ["4"] = true, c = true, h = true, i = true, p = true,
                q = true, r = true, s = true }
local function free_keys()
  local out = {}
  for _, k in ipairs { "a", "b", "d", "e", "f", "g", "j", "k", "l", "m", "n", "o", "t", "u", "v", "w", "x", "y", "z",
                       "0", "5", "6", "7", "8", "9" } do
    out[#out + 1] = k
  end
  return table.concat(out, " ")
end

local function number_param(model, name, level)
  local p = model:params()
  if type(p[name]) ~= "number" then
    local names = {}
    for k, v in pairs(p) do if type(v) == "number" then names[#names + 1] = k end end
    table.sort(names)
    error(("sn.live.bind: '%s' is not a number parameter of %s (valid: %s)"):format(name, model:name(),
      table.concat(names, ", ")), level + 1)
  end
end

-- The locals and upvalues the function `level` levels above the caller sees now (sn.live.bind's
-- caller: the script), so that an expression naming the script's locals reads in a plain run too,
-- where no console collects them.
local function scope_of(level)
  local scope = {}
  local info = debug.getinfo(level + 1, "f")
  for i = 1, info and info.func and math.huge or 0 do
    local name, v = debug.getupvalue(info.func, i)
    if not name then break end
    scope[name] = v
  end
  for i = 1, math.huge do
    local name, v = debug.getlocal(level + 1, i)
    if not name then break end
    if name:sub(1, 1) ~= "(" then scope[name] = v end  -- later locals shadow earlier ones
  end
  return scope
end

-- The binding's get, set and name, from its `param` (or its own get/set); then the range the
-- value must stay in when the param has one. `scope`: the caller's locals (scope_of).
local function accessors(o, level, scope)
  if o.get or o.set then
    if type(o.get) ~= "function" or type(o.set) ~= "function" then
      error("sn.live.bind: 'get' and 'set' must both be functions (get() -> number, set(number))", level + 1)
    end
    if type(o.name) ~= "string" then error("sn.live.bind: give a 'name' to show beside the value", level + 1) end
    return o.get, o.set, o.name
  end
  local p = o.param
  if type(p) ~= "string" then
    error("sn.live.bind: 'param' must be a string: \"truth.<parameter>\", \"input.<condition>\" or a Lua "
          .. "expression naming a number (\"net.layers[1].weight[2][3]\"); or give get and set functions", level + 1)
  end
  local model_param = p:match("^truth%.([%a_][%w_]*)$")
  if model_param then  -- the show's lighting model is immutable: a changed copy replaces it
    local spec = view_of.current_spec("sn.live.bind")
    if not check.type_is(spec.truth, "Lighting") then
      error(("sn.live.bind: '%s' needs a lighting model as the show's truth (sn.live.show{ truth = sn.lighting.* })")
        :format(p), level + 1)
    end
    number_param(spec.truth, model_param, level + 1)
    return function() return view_of.current_spec("sn.live.bind").truth:params()[model_param] end,
           function(v)
             local s = view_of.current_spec("sn.live.bind")
             s.truth = s.truth:with { [model_param] = v }
             s.draw.truth = view_of.drawer(s, "truth")
           end, p
  end
  local input = p:match("^input%.([%a_][%w_]*)$")
  if input then
    local spec = view_of.current_spec("sn.live.bind")
    local net = spec.network
    local names, cond = {}, nil
    for _, c in ipairs(check.type_is(net, "Mlp") and net:conditions() or {}) do
      names[#names + 1] = c.name
      if c.name == input then cond = c end
    end
    if not cond then
      error(("sn.live.bind: the show's network has no input '%s' (conditions: %s)"):format(input,
        #names > 0 and table.concat(names, ", ") or "none; see net:conditions()"), level + 1)
    end
    return function()
             for _, c in ipairs(net:conditions()) do if c.name == input then return c.value end end
           end,
           function(v) net:set_input(input, v) end, p, cond.min, cond.max  -- the trained range
  end
  -- A Lua expression, evaluated where console lines run (the script's top-level locals as its last
  -- good run left them, the globals), and before the first run ends or in a plain run, with the
  -- locals the sn.live.bind call saw.
  local get_chunk, err = loadstring("return " .. p, "=" .. p)
  local set_chunk = loadstring(p .. " = ...", "=" .. p)
  if not get_chunk or not set_chunk then
    error(("sn.live.bind: param '%s' is not an assignable Lua expression (%s)"):format(p, tostring(err)), level + 1)
  end
  local env = setmetatable({}, {
    __index = function(_, k)
      local l = S.locals
      if l and l[k] ~= nil then return l[k] end
      if scope[k] ~= nil then return scope[k] end
      return _G[k]
    end,
    __newindex = live._console_env(),
  })
  setfenv(get_chunk, env)
  setfenv(set_chunk, env)
  return function()
           local v = get_chunk()
           if type(v) ~= "number" then error(("%s is %s, not a number"):format(p, tostring(v)), 0) end
           return v
         end,
         function(v) set_chunk(v) end, p
end

-- sn.live.bind{ key = "k", param = "net.layers[1].weight[2][3]" | "truth.roughness" | "input.roughness",
--               step = 0.05, min = ..., max = ..., name = ..., get = fn, set = fn }
function live.bind(o)
  check.strict(o, { "key", "param", "step", "min", "max", "name", "get", "set" }, "sn.live.bind", 2)
  local key = type(o.key) == "string" and o.key:lower() or nil
  if not key or not key:match("^[%a%d]$") or TAKEN[key] then
    error(("sn.live.bind: key '%s' cannot be bound (free keys: %s; Shift + the key steps down)"):format(
      tostring(o.key), free_keys()), 2)
  end
  for _, k in ipairs { "step", "min", "max" } do
    if o[k] ~= nil and (type(o[k]) ~= "number" or o[k] ~= o[k] or math.abs(o[k]) == math.huge) then
      error(("sn.live.bind: '%s' must be a finite number"):format(k), 2)
    end
  end
  local b, min, max = { key = key }, nil, nil
  b.get, b.set, b.name, min, max = accessors(o, 2, scope_of(2))
  b.min, b.max = o.min or min, o.max or max
  b.name = o.name or b.name
  if b.min and b.max and b.min >= b.max then error("sn.live.bind: 'min' must be below 'max'", 2) end
  b.step = o.step or (b.min and b.max and (b.max - b.min) / 20) or 0.1
  if b.step <= 0 then error("sn.live.bind: 'step' must be > 0", 2) end
  local binds = S.running and (S.pending_binds or {}) or S.binds
  -- One binding per key (letters without case: Shift steps down): a second one replaces the
  -- first, which the user is told (within a run, or at the console; each run binds anew).
  local old = binds[key]
  if old and old.name ~= b.name then print(("[live] key %s was bound to %s; now to %s"):format(key, old.name, b.name)) end
  binds[key] = b
  if S.running then S.pending_binds = binds end
end

-- sn.live.binds() -> { {key, name, value}, ... } sorted by key (value nil when it cannot be read)
function live.binds()
  local out = {}
  for key, b in pairs(S.binds) do
    local ok, v = pcall(b.get)
    out[#out + 1] = { key = key, name = b.name, value = ok and v or nil }
  end
  table.sort(out, function(a, b) return a.key < b.key end)
  return out
end

-- For the loop: a key no built-in control took; `down` with Shift. Returns the terminal's line
-- when a bound value changed, nil otherwise (and an error message when the binding failed).
function live._key(key, down)
  local b = S.binds[key]
  if not b then return nil end
  local ok, r = pcall(function()
    local v = b.get() + (down and -b.step or b.step)
    if b.min then v = math.max(b.min, v) end
    if b.max then v = math.min(b.max, v) end
    b.set(v)
    return ("%s = %.6g"):format(b.name, b.get())
  end)
  if not ok then return nil, ("key %s (%s): %s"):format(key, b.name, tostring(r)) end
  return r
end

-- For the HUD: one line per binding, "k/K  name = value".
function live._bind_lines()
  local lines = {}
  for _, b in ipairs(live.binds()) do
    lines[#lines + 1] = ("%s/%s  %s = %s"):format(b.key, b.key:upper(), b.name,
      b.value and ("%.4g"):format(b.value) or "?")
  end
  return lines
end

-- A good run's bindings replace the last good run's (console bindings included: the script is
-- the truth); a failed run keeps them.
function bind.end_run(ok)
  if ok then S.binds = S.pending_binds or {} end
  S.pending_binds = nil
end

return bind
