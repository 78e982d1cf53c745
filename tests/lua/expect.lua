-- What the Lua tests share to check outcomes: expect.fails(f, text) calls f and asserts that it
-- raised an error whose message contains `text` (plain text, not a Lua pattern);
-- expect.same_params(a, b) is true when two networks' parameters are equal to the bit;
-- expect.fails_here(f, text) also asserts that the message names the test file's line.
local expect = {}

function expect.same_params(a, b)
  local pa, pb = a:params(), b:params()
  for i = 1, #pa do if pa[i] ~= pb[i] then return false end end
  return #pa == #pb
end

function expect.fails(f, text)
  local ok, err = pcall(f)
  assert(not ok, "expected an error mentioning " .. text)
  assert(tostring(err):find(text, 1, true), ("error %q does not mention %q"):format(tostring(err), text))
end

-- expect.fails_here(f, text): as fails, and the message starts with the calling test file's name:
-- the error names the script's line, not a runtime file's. (f must not end in a tail call of
-- the failing function, `return g()`: a tail call leaves no line to name.)
function expect.fails_here(f, text)
  local file = debug.getinfo(2, "S").short_src
  local ok, err = pcall(f)
  assert(not ok, "expected an error mentioning " .. text)
  err = tostring(err)
  assert(err:sub(1, #file + 1) == file .. ":", ("error %q does not name %s"):format(err, file))
  assert(err:find(text, 1, true), ("error %q does not mention %q"):format(err, text))
end

return expect
