#pragma once
// Elliptic integrals, one family per header (the layout of Boost.Math's ellint_*.hpp):
//  - elliptic_carlson.h:  Carlson's symmetric forms R_C, R_F, R_D, R_J (DLMF 19.16);
//  - elliptic_legendre.h: Legendre's F(phi|m) and Pi(n; phi|m) with the complement-argument
//    overloads, their cancellation-free difference forms and complete integrals, and the
//    convention (parameter m, not modulus k), domain and accuracy of all of them.
// Including this header includes both. The double-double Pi kernel behind ellint_pi<double>
// and its test hooks are private to the library (lib/src/math/elliptic_pi_dd.h).
#include "disklab/math/elliptic_carlson.h"
#include "disklab/math/elliptic_legendre.h"
