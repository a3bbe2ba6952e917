// Binding numbers of the irradiance sum (core/irradiance_sum.comp), included by the GLSL and by
// src/core/irradiance_sum.cpp: each number is written here only.
#ifndef PENUMBRA_IRRADIANCE_SUM_BINDINGS_H
#define PENUMBRA_IRRADIANCE_SUM_BINDINGS_H

#define IRRADIANCE_SUM_FIRST 0   // the sum so far (or the first contribution)
#define IRRADIANCE_SUM_SECOND 1  // the contribution added
#define IRRADIANCE_SUM_OUT 2

#endif
