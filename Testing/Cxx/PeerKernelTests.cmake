# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
# The point-set peers of the error-diffusion kernel.
bluenoise_add_test(TestPoissonDiskKernel LABELS peers)
bluenoise_add_test(TestWeightedSampleEliminationKernel LABELS peers)
bluenoise_add_test(TestPeerKernelsBlueNoise LABELS peers spectrum)
