-- Live mode's option checks: strict option tables, vectors, lights, sizes, view modes and the
-- runtime's userdata types, each error naming the call and the valid choices.
local check = {}

check.MODES = { "network", "truth", "error", "side" }
function check.is_mode(m)
  for _, v in ipairs(check.MODES) do if v == m then return true end end
  return false
end

-- Errors naming the mode and the valid ones, for sn.live.* calls at `level`.
function check.mode(m, what, level)
  if m ~= nil and not check.is_mode(m) then
    error(("%s: unknown mode '%s' (valid: %s)"):format(what, tostring(m), table.concat(check.MODES, ", ")), level + 1)
  end
end

function check.strict(t, valid, what, level)
  if type(t) ~= "table" then error(("%s expects a table of options, got %s"):format(what, type(t)), level + 1) end
  local ok = {}
  for _, k in ipairs(valid) do ok[k] = true end
  for k in pairs(t) do
    if not ok[k] then
      error(("%s: unknown option '%s' (valid: %s)"):format(what, tostring(k), table.concat(valid, ", ")), level + 1)
    end
  end
end

function check.vec3(v, what, level)
  if type(v) ~= "table" or #v ~= 3 then error(what .. " must be {x, y, z}", level + 1) end
  for i = 1, 3 do
    if type(v[i]) ~= "number" or v[i] ~= v[i] or v[i] == math.huge or v[i] == -math.huge then
      error(("%s[%d] must be a finite number, got %s"):format(what, i, tostring(v[i])), level + 1)
    end
  end
end

function check.light(light, what, level)
  if type(light) ~= "table" then error(what .. " must be a table { dir = {x, y, z} }", level + 1) end
  check.strict(light, { "dir" }, what, level + 1)
  check.vec3(light.dir, what .. ".dir", level + 1)
  local d = light.dir
  if d[1] == 0 and d[2] == 0 and d[3] == 0 then error(what .. ".dir must not be zero", level + 1) end
end

function check.size(size, what, level)
  if type(size) ~= "table" or type(size[1]) ~= "number" or type(size[2]) ~= "number" or size[1] < 1 or size[2] < 1
     or size[1] % 1 ~= 0 or size[2] % 1 ~= 0 then
    error(what .. " must be {width, height} in whole pixels >= 1", level + 1)
  end
end

-- A whole number in lo..hi (a count, a size in pixels): 1.5, -3 or NaN frames were 1 or 0 of
-- them, and 2^31 ran for ever.
function check.whole(v, lo, hi, what, level)
  if type(v) ~= "number" or v % 1 ~= 0 or not (v >= lo and v <= hi) then
    error(("%s must be a whole number in %d..%d, got %s"):format(what, lo, hi, tostring(v)), level + 1)
  end
end

function check.is_camera(v)
  return type(v) == "userdata" and getmetatable(v) == debug.getregistry().Camera
end

function check.type_is(v, name)
  return type(v) == "userdata" and getmetatable(v) == debug.getregistry()[name]
end

return check
