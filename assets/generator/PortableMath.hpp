#pragma once
// sin, cos and exp from + - * / only, so the generated files do not depend on
// the C library's versions of them: glibc, musl and the macOS libm may round
// the last bit differently, and a last bit can flip a printed digit or a pixel.
// IEEE 754 fixes the result of each basic operation, so these give the same
// bits everywhere (with floating-point contraction off, as -std=c++17 has it
// on GCC). Accurate to about 1e-12 in double, far below what a float keeps.

namespace stoa::assets {

double portableSin(double x);
double portableCos(double x);
double portableExp(double x);

} // namespace stoa::assets
