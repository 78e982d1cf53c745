#version 450
#include "a.glsl"
layout(local_size_x = LOCAL_SIZE) in;
void main() { f(); }

--8<--
0:3(5): error: `g' undeclared
0:1(1): warning: unused

--8<--
#include "b.glsl"
void f() { g(); }

--8<--
#define TWO 2
float g() { return TWO; }
