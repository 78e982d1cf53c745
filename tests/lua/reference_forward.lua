-- A double-precision forward pass written in Lua from net:params() (the flat layout: per layer,
-- weights [out][in] then biases [out]): the reference the gl tests compare against. A network
-- that encodes inputs reads them through tests/lua/encoding_reference.lua.
local encoding = require "encoding_reference"
local M = {}

-- Lua twins of user-defined activations, by name (tests add theirs).
M.custom = {}

-- s: the network's spec (its slope, omega, alpha). GELU in its tanh form, as shadenet's.
function M.act(kind, s, z)
  if M.custom[kind] then return M.custom[kind](z) end
  if kind == "tanh" then return math.tanh(z)
  elseif kind == "sigmoid" then return 1 / (1 + math.exp(-z))
  elseif kind == "relu" then return z > 0 and z or 0
  elseif kind == "leaky_relu" then return z > 0 and z or s.slope * z
  elseif kind == "sine" then return math.sin(s.omega * z)
  elseif kind == "softplus" then return math.max(z, 0) + math.log(1 + math.exp(-math.abs(z)))
  elseif kind == "squareplus" then return 0.5 * (z + math.sqrt(z * z + 4))
  elseif kind == "elu" then return z > 0 and z or s.alpha * (math.exp(z) - 1)
  elseif kind == "gelu" then return 0.5 * z * (1 + math.tanh(math.sqrt(2 / math.pi) * (z + 0.044715 * z ^ 3)))
  elseif kind == "swish" then return z / (1 + math.exp(-z))
  elseif kind == "exponential" then return math.exp(z) end
  assert(kind == "linear", "reference_forward: no twin for activation " .. tostring(kind))
  return z
end

-- params: the parameters in double (a table in net:params()' layout), default the net's own.
function M.forward(net, x, params)
  local s, p = net:spec(), params or net:params()
  local widths = { s.encoded_inputs }
  if next(s.encoding) then x = encoding.encode(net, x) end
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
      out[j] = M.act(kind, s, z)
    end
    a, off = out, b + nout
  end
  return a
end

-- The l2 loss (mean over rows and outputs) of `net` with parameters p over rows {x, y}.
function M.loss(net, rows, p)
  local sum, outs = 0, net:spec().outputs
  for _, r in ipairs(rows) do
    local out = M.forward(net, r[1], p)  -- in double: set_params would round p +- h to float
    for o = 1, outs do sum = sum + (out[o] - r[2][o]) ^ 2 end
  end
  return sum / (#rows * outs)
end

-- `steps` Adam steps (Kingma & Ba, with the bias corrections) from net:params() over one
-- minibatch of all `rows`, the gradient taken by central differences of M.loss (h = 1e-6):
-- what sn.train must do, computed without any of its code. adam = { lr, beta1, beta2, eps }.
function M.adam_steps(net, rows, steps, adam)
  local b1, b2 = adam.beta1 or 0.8, adam.beta2 or 0.9
  local p, m, v = net:params(), {}, {}
  for j = 1, #p do m[j], v[j] = 0, 0 end
  for t = 1, steps do
    local g = {}
    for j = 1, #p do
      local keep, h = p[j], 1e-6
      p[j] = keep + h
      local up = M.loss(net, rows, p)
      p[j] = keep - h
      local down = M.loss(net, rows, p)
      p[j] = keep
      g[j] = (up - down) / (2 * h)
    end
    for j = 1, #p do
      m[j] = b1 * m[j] + (1 - b1) * g[j]
      v[j] = b2 * v[j] + (1 - b2) * g[j] * g[j]
      p[j] = p[j] - adam.lr * (m[j] / (1 - b1 ^ t)) / (math.sqrt(v[j] / (1 - b2 ^ t)) + adam.eps)
    end
  end
  return p
end

return M
