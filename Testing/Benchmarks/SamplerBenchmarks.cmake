# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
bluenoise_add_benchmark(BenchmarkErrorDiffusionSampler)


