-- What the Lua tests share to check an error: expect.fails(f, text) calls f and asserts that it
-- raised an error whose message contains `text` (plain text, not a Lua pattern).
local expect = {}

function expect.fails(f, text)
  local ok, err = pcall(f)
  assert(not ok, "expected an error mentioning " .. text)
  assert(tostring(err):find(text, 1, true), ("error %q does not mention %q"):format(tostring(err), text))
end

return expect
