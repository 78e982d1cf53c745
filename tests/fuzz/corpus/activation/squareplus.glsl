vec4 s = sqrt(z * z + 4.0); return mix(2.0 / (s - z), 0.5 * (z + s), greaterThanEqual(z, vec4(0.0)));
--8<--
return 0.5 + 0.5 * z / sqrt(z * z + 4.0);