-- Long work inside a live session (training, recording) keeps the window alive: after each
-- epoch and before each recorded frame it calls the loop's tick, which shows the last good
-- picture with a progress bar (at most every 50 ms), reads the keys and says when the user
-- cancelled (Esc). Outside the live loop nothing changes.
local sn = require "shadenet.core"
local S = require "shadenet.live.state"
local live = sn.live

local busy = {}

-- Shows `text` and `fraction` (0..1) in the window; raises an error when the user cancelled.
function busy.tick(text, fraction)
  local tick = live._tick  -- set by the C++ loop while it runs
  if not (S.active and tick) then return end
  if tick(text, fraction or 0) then error("cancelled by the user (Esc)", 0) end
end

-- sn.train with the job's progress in the window (epoch, validation MSE, ETA), then the
-- script's own progress function if it gave one.
local plain_train = sn.train
function sn.train(o)
  if not (S.active and live._tick) or type(o) ~= "table" then return plain_train(o) end
  local copy = {}
  for k, v in pairs(o) do copy[k] = v end
  local nets = type(o.nets) == "table" and #o.nets or 1
  local epochs = type(o.epochs) == "number" and o.epochs or nil
  local t0, user, done = sn.clock(), o.progress, 0
  copy.progress = function(e)
    if user then user(e) end
    done = done + 1
    local fraction = epochs and done / (epochs * nets)
    local eta = fraction and (sn.clock() - t0) * (1 - fraction) / fraction
    busy.tick(("training%s: epoch %d%s  val MSE %.3g%s  (Esc cancels)"):format(
      nets > 1 and (" net %d/%d"):format(e.net, nets) or "", e.epoch, epochs and "/" .. epochs or "",
      e.val_mse, eta and ("  ETA %.1f s"):format(eta) or ""), fraction or 0)
  end
  return plain_train(copy)  -- a tail call: errors still name the script's line
end

return busy
