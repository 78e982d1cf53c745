-- Live mode's state that survives reloads: this module is never unloaded (only the script's
-- own modules are). Every shadenet.live.* module reads and writes this one table.
return {
  kept = {},        -- name -> { value, key, snapshot }
  spec = nil,       -- the sn.live.show{...} in force
  pending = nil,    -- the one given during the run in progress (committed when the run succeeds)
  running = false,  -- a (re)run of the watched script is in progress
  modules = {},     -- module name -> file, for modules `require`d from files
  files = {},       -- file -> true: modules and dofile'd scripts, watched for saves
  view = nil,       -- the last view the loop rendered ({mode, camera, light, width, height})
  loop_size = nil,  -- {w, h} the loop draws at (its window or --size), told at each run's start
  frames = 0,       -- frames rendered by the loop
  drawn = nil,      -- the last frame's parts: { view, network = Target, truth = Target } (probe)
  binds = {},       -- key -> sn.live.bind's binding in force
  pending_binds = nil,  -- the ones given during the run in progress (committed when it succeeds)
  requests = {},    -- actions asked of the loop from Lua (quit)
  out = {},         -- the loop's targets, reused between frames (by "what WxH")
  backend_said = nil,  -- the console's last line on which backend draws the network view
  line_snapshot = nil,  -- the networks as they were before the console line in progress
}
