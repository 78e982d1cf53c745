-- A double-precision forward pass written in Lua from net:params() (the flat layout: per layer,
-- weights [out][in] then biases [out]): the reference the gl tests compare against.
local M = {}

function M.act(kind, slope, z)
  if kind == "tanh" then return math.tanh(z)
  elseif kind == "sigmoid" then return 1 / (1 + math.exp(-z))
  elseif kind == "relu" then return z > 0 and z or 0
  elseif kind == "leaky_relu" then return z > 0 and z or slope * z end
  return z
end

function M.forward(net, x)
  local s, p = net:spec(), net:params()
  local widths = { s.inputs }
  for _, w in ipairs(s.hidden) do widths[#widths + 1] = w end
  widths[#widths + 1] = s.outputs
  local a, off = x, 0
  for l = 1, #widths - 1 do
    local nin, nout = widths[l], widths[l + 1]
    local kind = l == #widths - 1 and s.output_activation or s.activation
    local b, out = off + nin * nout, {}
    for j = 1, nout do
      local z = p[b + j]
      for i = 1, nin do z = z + p[off + (j - 1) * nin + i] * a[i] end
      out[j] = M.act(kind, s.slope, z)
    end
    a, off = out, b + nout
  end
  return a
end

return M
