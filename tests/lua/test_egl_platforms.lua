-- The headless context's EGL platforms (gl/egl_context.cpp, SHADENET_EGL_PLATFORM): `shadenet
-- --gl-info` prints what sn.gl_info() says; "device" runs through an EGL device (Mesa's software
-- device here, the GPU's on a GPU machine) and, on the same renderer, renders and trains to the
-- same bits as "surfaceless"; "auto" takes a hardware device when there is one; an unknown value
-- is a clear error naming the valid ones.
local sn = require "shadenet"
local C = require "script_check"

-- `--gl-info`'s "name: value" lines.
local function gl_info(platform)
  local code, out = C.run("--gl-info", {}, platform and { SHADENET_EGL_PLATFORM = platform } or nil)
  local t = {}
  for name, value in out:gmatch("\n([^:\n]+): ([^\n]*)") do t[name] = value end
  return code, t, out
end

-- This process's context, as --gl-info prints it under the same environment.
local info = sn.gl_info()
local code, t, out = gl_info(nil)
assert(code == 0, "--gl-info failed:\n" .. out)
assert(out:find("shadenet " .. sn.version .. " (build " .. sn.build .. ")\n", 1, true) == 1, out)
assert(t["platform"] == info.platform .. " (EGL)", out)
assert(t["GL renderer"] == info.renderer .. (info.software and " (software)" or ""), out)
assert(t["GL version"] == info.version and t["GL vendor"] == info.vendor and t["GLSL version"] == info.glsl_version, out)
assert(t["EGL vendor"] == info.egl_vendor and t["EGL vendor"] ~= "", out)
-- "EGL devices: none (why)" only when EGL named no device (Mesa here names its software device).
assert(t["EGL devices"] == (info.egl_devices ~= "" and info.egl_devices or nil), out)
assert(info.software ~= true or info.egl_devices == "", "Mesa names its software device: " .. info.egl_devices)
assert(t["max compute workgroup size"] == table.concat(info.max_workgroup_size, " x "), out)
assert(t["max compute workgroup invocations"] == tostring(info.max_workgroup_invocations), out)
assert(t["max compute shared memory"] == ("%d bytes"):format(info.max_shared_memory), out)
assert(t["max shader storage block"] == ("%.0f bytes"):format(info.max_ssbo_size), out)
assert(t["max uniform block"] == ("%d bytes"):format(info.max_uniform_block_size), out)
-- OpenGL 4.5's minimums (its specification, table 23.64 ff.): a context below them is misread.
assert(tonumber(info.glsl_version:match("^(%d+%.%d+)")) >= 4.5, info.glsl_version)
assert(info.max_workgroup_size[1] >= 1024 and info.max_workgroup_size[2] >= 1024 and info.max_workgroup_size[3] >= 64)
assert(info.max_workgroup_invocations >= 1024 and info.max_shared_memory >= 32768, out)
assert(info.max_ssbo_size >= 2 ^ 27 and info.max_uniform_block_size >= 16384, out)

-- The device platform: an EGL device, hardware first, else Mesa's software one (llvmpipe).
local dcode, dev, dout = gl_info("device")
assert(dcode == 0, "SHADENET_EGL_PLATFORM=device failed:\n" .. dout)
assert(dev["platform"] == "device (EGL)" and dev["EGL device extensions"], dout)
local dev_software = dev["GL renderer"]:find("(software)", 1, true) ~= nil
assert(dev_software == (dev["EGL device extensions"]:find("EGL_MESA_device_software", 1, true) ~= nil), dout)

-- auto takes a hardware device when there is one, else surfaceless (Mesa) before the software device.
local acode, auto, aout = gl_info("auto")
assert(acode == 0, "SHADENET_EGL_PLATFORM=auto failed:\n" .. aout)
if not dev_software then
  assert(auto["platform"] == "device (EGL)" and auto["GL renderer"] == dev["GL renderer"], aout)
end

local scode, surf, sout = gl_info("surfaceless")
if scode ~= 0 then
  -- A GPU driver alone (glvnd with NVIDIA's vendor file only) may have no surfaceless platform.
  assert(sout:find("no display could be initialised (SHADENET_EGL_PLATFORM=surfaceless", 1, true), sout)
  assert(not dev_software, "no surfaceless platform beside Mesa's software device:\n" .. sout)
  print("surfaceless: not offered here (" .. dev["GL renderer"] .. "); nothing to compare the device with")
else
  assert(surf["platform"] == "surfaceless (EGL)" and surf["EGL device extensions"] == nil, sout)
  if dev_software then assert(auto["platform"] == "surfaceless (EGL)", aout) end
end

-- Same renderer on both platforms: the same G-buffer, dataset, training (both gl kernels) and
-- fragment-shader picture, to the bit. Different renderers (a GPU and llvmpipe) round differently:
-- that comparison is the figure tests' (their stated tolerances), not this one's.
if scode == 0 and surf["GL renderer"] == dev["GL renderer"] then
  local dir = C.tmpdir("egl_platforms")
  local runs = {}
  for _, p in ipairs { "device", "surfaceless" } do
    local o = C.ok("tests/lua/egl_platform_child.lua", { dir .. "/" .. p .. ".exr" }, { SHADENET_EGL_PLATFORM = p })
    assert(o:match("^platform " .. p .. "\n"), o)
    runs[p] = { text = o:gsub("^platform %a+\n", ""), image = sn.image.load(dir .. "/" .. p .. ".exr") }
  end
  local d, s = runs.device, runs.surfaceless
  assert(select(2, d.text:gsub("net %d best_val_mse", "")) == 2, d.text)
  assert(d.text == s.text, "trained numbers differ between the platforms:\n" .. d.text .. "\n" .. s.text)
  local w, h = d.image:size()
  local covered, worst, lo, hi = 0, 0, math.huge, -math.huge
  for y = 1, h do
    for x = 1, w do
      local a, b = d.image:get(x, y), s.image:get(x, y)
      for k = 1, 4 do worst = math.max(worst, math.abs(a[k] - b[k])) end
      if a[4] > 0.5 then covered, lo, hi = covered + 1, math.min(lo, a[1]), math.max(hi, a[1]) end
    end
  end
  assert(covered > 300 and hi - lo > 0.05, ("a picture worth comparing: %d covered, red %g..%g"):format(covered, lo, hi))
  assert(worst == 0, "pictures differ between the platforms by up to " .. worst)
  os.execute("rm -rf '" .. dir .. "'")
  print(("device and surfaceless (%s): same training numbers, same %dx%d picture (%d covered pixels)"):format(
    dev["GL renderer"], w, h, covered))
end

-- An unknown platform names the valid ones.
local bcode, _, bout = gl_info("gpu")
assert(bcode == 1, bout)
assert(bout:find("shadenet: SHADENET_EGL_PLATFORM='gpu': unknown EGL platform (valid: auto, device, surfaceless)", 1, true), bout)
print("ok")
