-- Runs every ```lua block of a Markdown file as the docs promise: as it is, from the repository
-- root. `check(body, printed)`, if given, sees each example's code and the lines it printed.
local M = {}

-- Fences pair up: an opening one may name a language, a closing one never does (a ```python
-- block left open in datasets.md swallowed a section, headings and all, into code).
function M.check_fences(path, text)
  if not text then
    local f = assert(io.open(path, "r"), path .. " missing")
    text = f:read("*a")
    f:close()
  end
  local fences, at_line = 0, 0
  for line in (text .. "\n"):gmatch("([^\n]*)\n") do
    at_line = at_line + 1
    local info = line:match("^%s*```(.*)$")
    if info then
      assert(fences % 2 == 0 or info:match("^%s*$"), ("%s:%d: a fence naming '%s' where the block opened before it "
                                                     .. "should close"):format(path, at_line, info))
      fences = fences + 1
    end
  end
  assert(fences % 2 == 0, path .. ": a code block is never closed")
end

-- What an example printed keeps its promise when, token by token, each is the same text or a
-- number within float32's precision of it or rounding to it ("53.24" for 53.2407); "13:" (or ";", ",") promises 13; "..." inside a promised token
-- stands for any text, over as many printed tokens as it needs ("1.732...", "...:4:",
-- "...;"); a lone "..." promises whatever follows, and promised tokens past the printed ones
-- are a remark.
local function elision_pattern(promised)
  local parts = {}
  for part in (promised .. "..."):gmatch("(.-)%.%.%.") do parts[#parts + 1] = (part:gsub("%p", "%%%0")) end
  return "^" .. table.concat(parts, ".-") .. "$"
end

local function promise_kept(got, promise)
  local printed, promised = {}, {}
  for t in got:gmatch("%S+") do printed[#printed + 1] = t end
  for t in promise:gmatch("%S+") do promised[#promised + 1] = t end
  local function match(i, j)
    if i > #printed then return true end
    local e = promised[j]
    if not e then return false end
    if e == "..." then return true end
    if e:find("...", 1, true) then
      for k = i, #printed do
        if table.concat(printed, " ", i, k):match(elision_pattern(e)) and match(k + 1, j + 1) then return true end
      end
      return false
    end
    local p, n = tonumber(printed[i]), tonumber(e)
    local fraction = e:match("^[-+]?%d*%.(%d+)$")
    local tolerance = math.max(1e-6 * math.max(1, math.abs(n or 0)), fraction and 0.5 * 10 ^ -#fraction or 0)
    local same = printed[i] == e or (e:sub(1, -2) == printed[i] and e:sub(-1):match("[:;,]")) or
                 (p ~= nil and n ~= nil and math.abs(p - n) <= tolerance)
    return same and match(i + 1, j + 1)
  end
  return #printed > 0 and match(1, 1)
end

-- Every "--> value" an example promises (after a print on its line, or on lines of their own
-- after one) is what that print printed, a print in a loop its outputs in order; "--> e.g."
-- shows a value that varies (a system font's size). `printed_at[line]` holds what the print on
-- `line` of the body printed.
local function check_promises(path, line0, body, printed_at)
  local promises, order, last_print, n = {}, {}, nil, 0
  for code in (body .. "\n"):gmatch("([^\n]*)\n") do
    n = n + 1
    local comment = code:match("^%s*%-%-")
    if code:find("print(", 1, true) and not comment then last_print = n end
    local promise = code:match("%-%->%s*(.-)%s*$")
    local own_line = code:match("^%s*%-%->")
    if promise and (own_line or not comment) and not promise:match("^e%.g%.") then
      local at = own_line and last_print or (code:find("print(", 1, true) and n)
      assert(at, ("%s:%d: a promise with no print before it"):format(path, line0 + n - 1))
      if not promises[at] then promises[at], order[#order + 1] = {}, at end
      table.insert(promises[at], promise)
    end
  end
  for _, at in ipairs(order) do
    local got, promise = table.concat(printed_at[at] or {}, " "), table.concat(promises[at], " ")
    assert(promise_kept(got, promise),
           ("%s:%d: the example promises '%s' but printed '%s'"):format(path, line0 + at - 1, promise, got))
  end
end

function M.run(path, min_count, check)
  local f = assert(io.open(path, "r"), path .. " missing")
  local text = f:read("*a")
  f:close()
  M.check_fences(path, text)
  local count, pos = 0, 1
  while true do
    local s, e, body = text:find("```lua\n(.-)\n```", pos)
    if not s then break end
    local _, newlines = text:sub(1, s):gsub("\n", "")
    local line = newlines + 2
    local chunk, err = loadstring(body, "@" .. path .. ":" .. line)
    assert(chunk, err)
    local printed, printed_at = {}, {}
    setfenv(chunk, setmetatable({ print = function(...)
      local parts = {}
      for i = 1, select("#", ...) do parts[i] = tostring((select(i, ...))) end
      printed[#printed + 1] = table.concat(parts, " ")
      local at = debug.getinfo(2, "l").currentline
      printed_at[at] = printed_at[at] or {}
      table.insert(printed_at[at], printed[#printed])
    end }, { __index = _G }))
    local ok, msg = pcall(chunk)
    assert(ok, ("%s example at line %d failed: %s"):format(path, line, tostring(msg)))
    check_promises(path, line, body, printed_at)
    if check then check(body, printed) end
    count = count + 1
    pos = e + 1
  end
  assert(count >= min_count, ("expected at least %d examples in %s, found %d"):format(min_count, path, count))
  return count
end

return M
