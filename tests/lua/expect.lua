-- What the Lua tests share to check outcomes: expect.fails(f, text) calls f and asserts that it
-- raised an error whose message contains `text` (plain text, not a Lua pattern);
-- expect.same_params(a, b) is true when two networks' parameters are equal to the bit.
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

return expect
