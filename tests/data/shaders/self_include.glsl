// Includes itself: the loader reports the cycle.
#include "self_include.glsl"
float self_included() { return 1.0; }
