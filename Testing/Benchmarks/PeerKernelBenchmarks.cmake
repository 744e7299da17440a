# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
# The smoke run (CTest): the smallest cases.
bluenoise_add_benchmark(BenchmarkPeerKernels SMOKE "L:64/g255:8/")
