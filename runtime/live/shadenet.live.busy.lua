-- Long work inside a live session (training, recording) keeps the window alive: during training
-- and before each recorded frame it calls the loop's tick, which shows the last good
-- picture with a progress bar (sn.train ticks every 50 ms), reads the keys and says when the user
-- cancelled (Esc). Outside the live loop nothing changes.
local sn = require "shadenet.core"
local S = require "shadenet.live.state"
local live = sn.live

local busy = {}

-- Shows `text` and `fraction` (0..1) in the window; raises an error when the user cancelled (Esc)
-- or closed the window.
function busy.tick(text, fraction)
  local tick = rawget(live, "_tick")  -- set by the C++ loop while it runs (raw: sn.live is strict)
  if not (S.active and tick) then return end
  local why = tick(text, fraction or 0)
  if why then error(why, 0) end
end

-- sn.train with the job's progress in the window (epoch, step, validation MSE, ETA) about
-- every 50 ms, within epochs too, then the script's own progress and tick functions if it gave
-- them. Esc stops the training at its next step and fails the run, so the last good state stays.
local plain_train = sn.train
function sn.train(o)
  if not (S.active and rawget(live, "_tick")) or type(o) ~= "table" then return plain_train(o) end
  local copy = {}
  for k, v in pairs(o) do copy[k] = v end
  local nets = type(o.nets) == "table" and #o.nets or 1
  local t0, user_progress, user_tick = sn.clock(), o.progress, o.tick
  local val_mse, cancelled = "", false
  copy.progress = function(e)
    val_mse = nets > 1 and "" or ("  val MSE %.3g"):format(e.val_mse)
    if user_progress then return user_progress(e) end
  end
  copy.tick = function(t)
    local eta = t.fraction > 0 and (sn.clock() - t0) * (1 - t.fraction) / t.fraction
    local text = ("training%s: epoch %d/%d, step %d/%d%s%s  (Esc cancels)"):format(
      nets > 1 and (" %d nets"):format(nets) or "", t.epoch, t.epochs, t.step, t.steps, val_mse,
      eta and ("  ETA %.1f s"):format(eta) or "")
    local why = live._tick(text, t.fraction)
    if why then
      cancelled = t
      cancelled.why = why
      return "stop"
    end
    if user_tick then return user_tick(t) end
  end
  copy.tick_seconds = math.min(0.05, type(o.tick_seconds) == "number" and o.tick_seconds or 0.05)
  -- A tick before the training sets up (seconds, for millions of rows): the bar shows at once,
  -- and the keys pressed meanwhile are the training's (the loop leaves ticking work to its ticks).
  local why = live._tick(("training%s: setting up  (Esc cancels)"):format(nets > 1 and (" %d nets"):format(nets) or ""), 0)
  if why then error(("sn.train: %s before its first step; the last good state stays"):format(why), 2) end
  -- Errors name the script's line (level 2), not this wrapper's.
  local ok, results = pcall(plain_train, copy)
  if not ok then error(results, 2) end
  if cancelled then
    error(("sn.train: %s in epoch %d of %d; the last good state stays"):format(cancelled.why, cancelled.epoch,
                                                                               cancelled.epochs), 2)
  end
  return results
end

return busy
