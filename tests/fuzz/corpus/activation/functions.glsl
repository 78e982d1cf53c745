const float k = 2.0; /* c */ vec4 y = x; y *= k; y += smoothstep(-1.0, 1.0, x) - fract(x) + mod(x, 3.0);
bool far = p > 1.0 && !(p < -1.0) || p == 0.5; return far ? pow(abs(y), vec4(1.5)) + atan(y) : log2(exp2(y)) + inversesqrt(1.0 + y * y);
--8<--
return step(0.0, x) * sign(x) + clamp(x, -1.0, 1.0) + tanh(x) * cosh(x) - sinh(x) + asinh(x) + acos(0.5) + asin(0.5) + radians(degrees(x));