-- JSON for results files: run records, run.json. Objects are written with sorted keys so the
-- same data always gives the same bytes (shard + merge can be compared with a plain diff).
-- JSON has no NaN or infinity: they are written as the strings "nan", "inf", "-inf" and read
-- back as numbers, so a non-finite value is never silently turned into null.
local json = {}

local function is_array(t)
  local n = #t
  if n == 0 then return next(t) == nil end
  local count = 0
  for _ in pairs(t) do count = count + 1 end
  return count == n
end

local escapes = { ['"'] = '\\"', ['\\'] = '\\\\', ['\b'] = '\\b', ['\f'] = '\\f',
                  ['\n'] = '\\n', ['\r'] = '\\r', ['\t'] = '\\t' }

local function encode_string(s)
  return '"' .. s:gsub('[%c"\\]', function(c)
    return escapes[c] or string.format("\\u%04x", c:byte())
  end) .. '"'
end

local function encode_number(x)
  if x ~= x then return '"nan"' end
  if x == math.huge then return '"inf"' end
  if x == -math.huge then return '"-inf"' end
  if x == math.floor(x) and math.abs(x) < 2^53 then return string.format("%d", x) end
  -- The shortest text that reads back as the same double (0.7, not 0.69999999999999996).
  for digits = 15, 16 do
    local s = string.format("%." .. digits .. "g", x)
    if tonumber(s) == x then return s end
  end
  return string.format("%.17g", x)
end

local function encode(v, indent, depth, path, seen)
  local t = type(v)
  if t == "nil" then return "null" end
  if t == "boolean" then return tostring(v) end
  if t == "number" then return encode_number(v) end
  if t == "string" then return encode_string(v) end
  if t ~= "table" then error("json: cannot encode a " .. t .. " at " .. path, 0) end
  if seen[v] then error("json: cycle at " .. path, 0) end
  seen[v] = true
  local pad = indent and ("\n" .. string.rep(indent, depth + 1)) or ""
  local close = indent and ("\n" .. string.rep(indent, depth)) or ""
  local sep = indent and ": " or ":"
  local parts = {}
  local out
  if is_array(v) then
    if next(v) == nil then seen[v] = nil return "[]" end
    -- Arrays of plain values stay on one line: curves read better that way.
    local flat = true
    for i = 1, #v do if type(v[i]) == "table" then flat = false break end end
    for i = 1, #v do
      local item = encode(v[i], indent, depth + 1, path .. "[" .. i .. "]", seen)
      parts[i] = flat and item or pad .. item
    end
    if flat then
      out = "[" .. table.concat(parts, indent and ", " or ",") .. "]"
    else
      out = "[" .. table.concat(parts, ",") .. close .. "]"
    end
  else
    local keys = {}
    for k in pairs(v) do
      if type(k) ~= "string" then error("json: non-string key " .. tostring(k) .. " at " .. path, 0) end
      keys[#keys + 1] = k
    end
    table.sort(keys)
    for i, k in ipairs(keys) do
      parts[i] = pad .. encode_string(k) .. sep .. encode(v[k], indent, depth + 1, path .. "." .. k, seen)
    end
    out = "{" .. table.concat(parts, ",") .. close .. "}"
  end
  seen[v] = nil
  return out
end

-- json.encode(value [, indent]) -> string; indent = "  " pretty-prints.
function json.encode(v, indent)
  return encode(v, indent, 0, "$", {})
end

local specials = { nan = 0 / 0, inf = math.huge, ["-inf"] = -math.huge }

-- json.decode(text [, what]) -> value; errors name `what` and the byte offset.
function json.decode(s, what)
  what = what or "json"
  local pos = 1
  local function fail(msg) error(string.format("%s: %s at byte %d", what, msg, pos), 0) end
  local function ws() pos = s:find("[^ \t\r\n]", pos) or #s + 1 end
  local value
  local function str()
    local out, i = {}, pos + 1
    while true do
      local c = s:sub(i, i)
      if c == "" then fail("unterminated string") end
      if c == '"' then pos = i + 1 break end
      if c == "\\" then
        local e = s:sub(i + 1, i + 1)
        local map = { b = "\b", f = "\f", n = "\n", r = "\r", t = "\t", ['"'] = '"', ["\\"] = "\\", ["/"] = "/" }
        if map[e] then out[#out + 1] = map[e]; i = i + 2
        elseif e == "u" then
          local code = tonumber(s:sub(i + 2, i + 5), 16)
          if not code then fail("bad \\u escape") end
          if code < 128 then out[#out + 1] = string.char(code)
          elseif code < 2048 then out[#out + 1] = string.char(192 + math.floor(code / 64), 128 + code % 64)
          else out[#out + 1] = string.char(224 + math.floor(code / 4096), 128 + math.floor(code / 64) % 64, 128 + code % 64) end
          i = i + 6
        else fail("bad escape") end
      else
        out[#out + 1] = c; i = i + 1
      end
    end
    return table.concat(out)
  end
  function value()
    ws()
    local c = s:sub(pos, pos)
    if c == "{" then
      pos = pos + 1
      local t = {}
      ws()
      if s:sub(pos, pos) == "}" then pos = pos + 1 return t end
      while true do
        ws()
        if s:sub(pos, pos) ~= '"' then fail("object key expected") end
        local k = str()
        ws()
        if s:sub(pos, pos) ~= ":" then fail("':' expected") end
        pos = pos + 1
        t[k] = value()
        ws()
        local d = s:sub(pos, pos)
        pos = pos + 1
        if d == "}" then return t end
        if d ~= "," then fail("',' or '}' expected") end
      end
    elseif c == "[" then
      pos = pos + 1
      local t = {}
      ws()
      if s:sub(pos, pos) == "]" then pos = pos + 1 return t end
      while true do
        t[#t + 1] = value()
        ws()
        local d = s:sub(pos, pos)
        pos = pos + 1
        if d == "]" then return t end
        if d ~= "," then fail("',' or ']' expected") end
      end
    elseif c == '"' then
      local v = str()
      if specials[v] then return specials[v] end
      return v
    elseif s:find("^true", pos) then pos = pos + 4 return true
    elseif s:find("^false", pos) then pos = pos + 5 return false
    elseif s:find("^null", pos) then pos = pos + 4 return nil
    else
      local num = s:match("^-?%d+%.?%d*[eE]?[-+]?%d*", pos)
      if not num or num == "" or not tonumber(num) then fail("unexpected '" .. c .. "'") end
      pos = pos + #num
      return tonumber(num)
    end
  end
  local v = value()
  ws()
  if pos <= #s then fail("trailing characters") end
  return v
end

return json
