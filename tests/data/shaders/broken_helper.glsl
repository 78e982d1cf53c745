// A helper with a deliberate compile error on line 5.

float twice(float x)
{
    return undeclared_thing * 2.0;
}
