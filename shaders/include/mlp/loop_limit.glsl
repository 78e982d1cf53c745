// llvmpipe ends every loop of a shader invocation once 65,535 iterations have run in it, in
// total, silently: from then on each loop stops after its first pass. Called after the
// invocation's last other loop, this says whether any loop was cut: its own two passes both run
// only while budget is left, and the budget only shrinks. (A counting loop earlier on proves only
// the budget it spends itself: a kernel that checked so and then wrote its results in a loop
// wrote part of them, unnoticed.) The includer declares `uniform int u_zero` (0, never set).
bool mlp_loops_were_cut() {
  int passes = 0;
  for (int k = 0; k < 2 + u_zero; ++k) ++passes;
  return passes < 2;
}
