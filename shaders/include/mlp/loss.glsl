// The training loss of runtime/nn/loss.h per output component (MLP_LOSS: 0 l2, 1 l1,
// 2 relative_l2, 3 huber with MLP_LOSS_DELTA), of the error e = y - target and the target:
// its value and its derivative with respect to y. Padding (e = 0) gives 0 for both.
#define MLP_LOSS_L2 0
#define MLP_LOSS_L1 1
#define MLP_LOSS_RELATIVE_L2 2
#define MLP_LOSS_HUBER 3

// A sample's squared error for the divergence rule's bound: its l2 loss is that already (the
// separate sum then goes unused and the compiler drops it).
#if MLP_LOSS == MLP_LOSS_L2
#define MLP_SQUARED_ERROR(loss, se) (loss)
#else
#define MLP_SQUARED_ERROR(loss, se) (se)
#endif

vec4 mlp_loss(vec4 e, vec4 t) {
#if MLP_LOSS == MLP_LOSS_L1
  return abs(e);
#elif MLP_LOSS == MLP_LOSS_RELATIVE_L2
  return e * e / (t * t + 0.01);
#elif MLP_LOSS == MLP_LOSS_HUBER
  vec4 a = abs(e);
  return mix(MLP_LOSS_DELTA * (a - 0.5 * MLP_LOSS_DELTA), 0.5 * e * e, lessThanEqual(a, vec4(MLP_LOSS_DELTA)));
#else
  return e * e;
#endif
}

vec4 mlp_loss_grad(vec4 e, vec4 t) {
#if MLP_LOSS == MLP_LOSS_L1
  return sign(e);
#elif MLP_LOSS == MLP_LOSS_RELATIVE_L2
  return 2.0 * e / (t * t + 0.01);
#elif MLP_LOSS == MLP_LOSS_HUBER
  return clamp(e, -MLP_LOSS_DELTA, MLP_LOSS_DELTA);
#else
  return 2.0 * e;
#endif
}
