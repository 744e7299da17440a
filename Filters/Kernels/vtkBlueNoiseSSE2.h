// SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file   vtkBlueNoiseSSE2.h
 * @brief  Whether the module's SSE2 code paths are built: BLUENOISE_SSE2 is
 *         1 where the compiler targets SSE2 (every x86-64 one), unless
 *         BLUENOISE_NO_SSE2 is defined (the CMake option BLUENOISE_SSE2=OFF).
 *
 * Each SSE2 path has a plain one beside it, built on other processors, that
 * gives the same results; the option builds the plain ones on x86-64 too, so
 * that the tests check them (scripts/test.sh's VTK-only stage).
 */
#ifndef vtkBlueNoiseSSE2_h
#define vtkBlueNoiseSSE2_h

#if defined(__SSE2__) && !defined(BLUENOISE_NO_SSE2)
#define BLUENOISE_SSE2 1
#include <emmintrin.h>
#else
#define BLUENOISE_SSE2 0
#endif

#endif
