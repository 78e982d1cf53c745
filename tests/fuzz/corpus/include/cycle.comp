#include "a.glsl"

--8<--

--8<--
#include "b.glsl"

--8<--
#include "a.glsl"
