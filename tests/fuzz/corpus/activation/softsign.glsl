x / (1.0 + abs(x))
--8<--
vec4 d = 1.0 + abs(x); return 1.0 / (d * d);