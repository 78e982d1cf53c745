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
    local printed = {}
    setfenv(chunk, setmetatable({ print = function(...)
      local parts = {}
      for i = 1, select("#", ...) do parts[i] = tostring((select(i, ...))) end
      printed[#printed + 1] = table.concat(parts, " ")
    end }, { __index = _G }))
    local ok, msg = pcall(chunk)
    assert(ok, ("%s example at line %d failed: %s"):format(path, line, tostring(msg)))
    if check then check(body, printed) end
    count = count + 1
    pos = e + 1
  end
  assert(count >= min_count, ("expected at least %d examples in %s, found %d"):format(min_count, path, count))
  return count
end

return M
