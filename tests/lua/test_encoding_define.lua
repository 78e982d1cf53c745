-- sn.encoding.define: a user's encoding goes through the registry the built-ins use. A copy of
-- the built-in frequency encoding defined from Lua (examples/lua_frequency.lua) must give
-- exactly what the built-in gives:
-- the same encoded rows, the same training on the cpu and the gl backend, the same pictures on
-- both render backends. Then: several such nets in one cpu job (their Lua twin runs on one
-- thread), checkpoints by definition, redefinition (live mode), and the checks that refuse a
-- broken definition before it is registered. (A new encoding against its own reference, through
-- training, checkpoints and the fragment shader: tests/lua/test_mlp_encoding.lua.)
local sn = require "shadenet"
local C = require "script_check"

dofile("examples/lua_frequency.lua")  -- defines lua_frequency: the built-in, word for word
assert(table.concat(sn.encoding.names(), " "):find("triangle_wave lua_frequency", 1, true))

local function make(kind, seed)
  return sn.mlp { inputs = { "normal", "view", "uv" }, hidden = { 16, 16 }, seed = seed,
                  encoding = { uv = { kind, bands = 5 }, view = { kind, bands = 2, include_input = false } } }
end
local function same(a, b, what)
  local pa, pb = a:params(), b:params()
  assert(#pa == #pb, what)
  for i = 1, #pa do assert(pa[i] == pb[i], ("%s: parameter %d: %.9g vs %.9g"):format(what, i, pa[i], pb[i])) end
end
local builtin, mine = make("frequency", 3), make("lua_frequency", 3)
assert(tostring(mine) == tostring(builtin):gsub("frequency", "lua_frequency"), tostring(mine))
same(mine, builtin, "the same initial weights")
local x = { 0.48, 0.6, 0.64, 0.36, 0.48, 0.8, 0.731, 0.0625 }
local eb, em = builtin:encode(x), mine:encode(x)
assert(#em == #eb and #em == 37)
for i = 1, #eb do assert(em[i] == eb[i], ("encoded input %d: %.17g vs %.17g"):format(i, em[i], eb[i])) end

-- Training: the same steps, bit for bit, on either backend.
local scene = sn.scene { mesh = "meshes/test_blob.glb", size = { 64, 48 }, views = { count = 2, elevation = 20 } }
local data = scene:dataset { inputs = { "normal", "view", "uv" }, target = sn.lighting.phong {}, samples = 3000, seed = 2 }
for _, backend in ipairs(sn.backends()) do
  local a, b = make("frequency", 5), make("lua_frequency", 5)
  local ra = sn.train { nets = a, data = data, epochs = 2, backend = backend, adam = { lr = 3e-3 } }[1]
  local rb = sn.train { nets = b, data = data, epochs = 2, backend = backend, adam = { lr = 3e-3 } }[1]
  assert(rb.val_mse[2] == ra.val_mse[2] and rb.val_mse[2] < ra.val_mse[1] * 1.5, backend .. ": the same curve")
  same(b, a, backend .. ": trained weights")
  print(("%s: lua_frequency trains exactly as frequency (val MSE %.4g)"):format(backend, rb.val_mse[2]))
end

-- Several nets with a user's encoding in one cpu job: each as it trains alone.
local together = { make("lua_frequency", 7), make("lua_frequency", 8), make("frequency", 9) }
local alone = { together[1]:clone(), together[2]:clone(), together[3]:clone() }
sn.train { nets = together, data = data, epochs = 1, backend = "cpu" }
for i = 1, 3 do
  sn.train { nets = alone[i], data = data, epochs = 1, backend = "cpu" }
  same(together[i], alone[i], "net " .. i .. " of a job")
end

-- Rendering: auto picks the fragment shader (the Lua twin would run one pixel at a time);
-- backend = "cpu" runs it anyway; both agree with the built-in's picture.
local g = scene:gbuffer { view = 1, attributes = { "normal", "view", "uv" } }
local ref = together[3]
local mine_r = make("lua_frequency", 9)
mine_r:set_params(ref:params())
local want = ref:render(g, { backend = "gl" })
for _, backend in ipairs { "auto", "cpu" } do
  local img = mine_r:render(g, { backend = backend })
  local info = sn.render_info()
  if backend == "auto" then
    assert(info.backend == "gl" and info.reason:find("encoding 'lua_frequency' is a Lua definition", 1, true), info.reason)
  end
  local w, h = img:size()
  local worst, covered = 0, 0
  for py = 1, h do
    for px = 1, w do
      local p, q = img:get(px, py), want:get(px, py)
      if q[4] > 0 then
        covered = covered + 1
        for c = 1, 3 do worst = math.max(worst, math.abs(p[c] - q[c])) end
      end
    end
  end
  assert(covered > 300 and worst < 1e-5, ("%s render: %d pixels, worst %g"):format(backend, covered, worst))
  print(("render %s (%s): within %.1g of the built-in's"):format(backend, info.backend, worst))
end

-- Checkpoints carry the definition's GLSL: loading needs the name defined, the same way.
local tmp = C.tmpdir("encdef")
local path = tmp .. "/mine.snmlp"
mine:save(path)
assert(tostring(sn.load(path)) == tostring(mine))
local child = tmp .. "/child.lua"
local f = assert(io.open(child, "w"))
f:write('local sn = require "shadenet"\nsn.load(' .. ("%q"):format(path) .. ')\n')
f:close()
local code, out = C.run(child)
assert(code ~= 0 and out:find("the network encodes input 'view' with 'lua_frequency', which is not defined; define it " ..
                                "before sn.load with sn.encoding.define{ name = \"lua_frequency\", glsl = \"if (keep)", 1, true), out)

-- Defining a name again replaces it (a script re-run in live mode); a checkpoint saved under
-- the earlier definition then says so.
local function powers(signed)
  sn.encoding.define {
    name = "powers", count = { "degree", max = 4, default = 2 },
    outputs = function(w, n) return w * n end,
    glsl = signed and "int c = j / n; float p = x[c]; for (int i = c * n; i < j; ++i) p *= x[c]; return p;"
                   or "int c = j / n; float p = abs(x[c]); for (int i = c * n; i < j; ++i) p *= abs(x[c]); return p;",
    lua = function(x, n)
      local out = {}
      for c = 1, #x do
        for k = 1, n do out[#out + 1] = (signed and x[c] or math.abs(x[c])) ^ k end
      end
      return out
    end,
  }
end
powers(false)
local p1 = sn.mlp { inputs = { "uv" }, hidden = { 4 }, encoding = { uv = "powers" } }
assert(p1:encode({ -0.5, 0.25 })[1] == 0.5)
p1:save(tmp .. "/p1.snmlp")
powers(true)
assert(sn.mlp { inputs = { "uv" }, hidden = { 4 }, encoding = { uv = "powers" } }:encode({ -0.5, 0.25 })[1] == -0.5)
local ok, err = pcall(sn.load, tmp .. "/p1.snmlp")
assert(not ok and err:find("encoding 'powers' is defined differently from the network's (glsl = \"int c = j / n; float p = abs",
                           1, true), err)

-- A definition that fails its checks is not registered, and an earlier one of its name stays.
local function refused(def, pattern)
  local names = table.concat(sn.encoding.names(), " ")
  local ok, e = pcall(sn.encoding.define, def)
  assert(not ok and e:find(pattern, 1, true), tostring(e))
  assert(table.concat(sn.encoding.names(), " ") == names, "the registry is unchanged")
end
local function def(o)
  local d = { name = "broken", outputs = 1, glsl = "return x[0];", lua = function(x) return { x[1] } end }
  for k, v in pairs(o) do d[k] = v end
  return d
end
-- (the script line in front when not called through pcall: tests/errors/encoding_glsl_error.lua)
refused(def { glsl = "return cosine(x[0]);" }, "its GLSL does not compile:\nGLSL compile error in shaders/encoding_check.comp:\nencoding broken:1: error: no function with name 'cosine'")
refused(def { glsl = "return 2.0 * x[0];" }, "its GLSL gives")
refused(def { lua = function(x) return { x[1], x[1] } end }, "lua returned 2 numbers; outputs says 1 for an input of 1")
refused(def { lua = function(x) return { 0 / 0 } end }, "encoding 'broken': lua returned nan as output 1 for the input {")
refused(def { lua = function() error("boom") end }, "encoding 'broken': lua failed: ")
refused(def { outputs = 0 }, "outputs for an input of 1 component is 0; it must be 1..256")
refused(def { name = "frequency" }, "encoding 'frequency' is built in; choose another name")
refused(def { name = "Bad Name" }, "use lower-case letters, digits and _")
refused(def { count = { "bands", min = 3, max = 2 } }, "needs 1 <= min <= default <= max <= 64")
refused(def { input_width = 5 }, "option 'input_width': 1..4")
refused(def { name = "powers", glsl = "return nope;" }, "encoding 'powers': its GLSL does not compile")
assert(sn.mlp { inputs = { "uv" }, hidden = { 4 }, encoding = { uv = "powers" } }:encode({ -0.5, 0.25 })[1] == -0.5,
       "the earlier definition of powers stays")
ok, err = pcall(sn.mlp, { inputs = { "uv" }, hidden = { 4 }, encoding = { uv = { "powers", degree = 9 } } })
assert(not ok and err:find("degree must be 1..4, got 9", 1, true), err)
-- A redefinition that changes the output count: networks built before keep the definition they
-- were built with (tests/lua/test_redefine_networks.lua: on every backend), new ones get the new.
local function dup(k)
  sn.encoding.define { name = "dup", outputs = function(w) return k * w end, glsl = "return x[j / " .. k .. "];",
                       lua = function(x) local o = {} for c = 1, #x do for _ = 1, k do o[#o + 1] = x[c] end end return o end }
end
dup(1)
local before = sn.mlp { inputs = { "uv" }, hidden = { 4 }, encoding = { uv = "dup" } }
local out = before:forward { 0.1, 0.2 }
dup(2)
assert(before:forward { 0.1, 0.2 }[1] == out[1] and #before:encode { 0.1, 0.2 } == 2, "the network built before")
assert(#sn.mlp { inputs = { "uv" }, hidden = { 4 }, encoding = { uv = "dup" } }:encode { 0.1, 0.2 } == 4, "a new network")
-- Past the definition's sample inputs (+-300), the data decides: the cpu backend, which trains on
-- the twin's values, holds the twin to the GLSL on every row first. A GLSL that clamps at 1000
-- and a twin that does not were taken, and a world position of 1040 trained 1.04 on cpu and 1 on
-- gl; now the error names the defining line, the row's input and both values.
local far_line = debug.getinfo(1, "l").currentline + 1
sn.encoding.define { name = "far", outputs = function(w) return w end, glsl = "return clamp(x[j], -1000.0, 1000.0) / 1000.0;",
                     lua = function(x) local o = {} for i = 1, #x do o[i] = x[i] / 1000 end return o end }
local function far_data(top)
  local xs, ys = {}, {}
  for i = 1, 50 do xs[i], ys[i] = { top * i / 50, 0.5, -3 }, { 0.1, 0.2, 0.3 } end
  return sn.dataset { x = xs, y = ys, input_names = { "world_position" } }
end
local function far_net() return sn.mlp { inputs = { "world_position" }, hidden = { 4 }, encoding = { world_position = "far" } } end
ok, err = pcall(sn.train, { nets = far_net(), data = far_data(2000), epochs = 1, backend = "cpu" })
local at, v, twin = tostring(err):match("encoding 'far' %(defined at ([^)]*)%) of input 'world_position': on %a+ row %d+, "
                                        .. "world_position = {(%d+), 0%.5, %-3}, its GLSL gives 1 as output 1, its Lua twin ([%d.]+); "
                                        .. "the cpu backend trains on the twin's values, gl on the GLSL's")
assert(not ok and at == debug.getinfo(1, "S").short_src .. ":" .. far_line and tonumber(v) > 1000 and
       math.abs(tonumber(twin) - tonumber(v) / 1000) < 1e-6, tostring(err))
-- Data within the range where both agree trains.
assert(sn.train { nets = far_net(), data = far_data(900), epochs = 1, backend = "cpu" }[1].val_mse[1] >= 0)

-- A job encodes its rows once per distinct encoding, not once more per network for the
-- untrained MSE and the diagnostics: four nets cost the Lua twin what one does.
local calls = 0
sn.encoding.define { name = "counted", outputs = function(w) return 2 * w end, glsl = "return j < w ? x[j] : sin(x[j - w]);",
                     lua = function(x)
                       calls = calls + 1
                       local o = {}
                       for c = 1, #x do o[c], o[#x + c] = x[c], math.sin(x[c]) end
                       return o
                     end }
local rows = sn.dataset.sample { target = sn.lighting.phong {}, n = 500, seed = 1 }
local ntrain, nval = rows:counts()
local function encoded_for(count)
  local nets = {}
  for k = 1, count do nets[k] = sn.mlp { inputs = { "normal", "view" }, hidden = { 4 }, seed = k, encoding = { normal = "counted" } } end
  calls = 0
  sn.train { nets = nets, data = rows, epochs = 1, backend = "cpu" }
  return calls
end
local one, four = encoded_for(1), encoded_for(4)
assert(one == four and one <= ntrain + 2 * nval, ("rows encoded: %d for one net, %d for four (%d train + %d val rows)"):format(one, four, ntrain, nval))
C.rm(tmp)
print("encoding define: ok")
