return 0.5 * z * (1.0 + sn_gelu_tanh(z));
--8<--
vec4 t = sn_gelu_tanh(z);
return 0.5 * (1.0 + t) + 0.5 * z * (1.0 - t * t) * 0.7978845608028654 * (1.0 + 0.134145 * z * z);