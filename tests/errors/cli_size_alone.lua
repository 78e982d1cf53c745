-- args: --size 10x10
-- expect: shadenet: --size is the window's \(or live mode's view's\) size: give --window or --watch with it
-- --size without --window or --watch was ignored without a word.
print("never runs")
