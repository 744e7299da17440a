# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
# Tests of the 3D blue-noise spectrum metric (vtkBlueNoiseSpectrumKernel and
# the vtkBlueNoiseSpectrum filter).
bluenoise_add_test(TestBlueNoiseSpectrumSinglePoint LABELS spectrum)
bluenoise_add_test(TestBlueNoiseSpectrumLattice LABELS spectrum)
bluenoise_add_test(TestBlueNoiseSpectrumWhiteNoise LABELS spectrum TIMEOUT 300)
bluenoise_add_test(TestBlueNoiseSpectrumParseval LABELS spectrum)
bluenoise_add_test(TestBlueNoiseSpectrumDirectDFT LABELS spectrum TIMEOUT 300)
bluenoise_add_test(TestBlueNoiseSpectrumEdgeCases LABELS spectrum)
bluenoise_add_test(TestBlueNoiseSpectrumPipeline LABELS spectrum)
bluenoise_add_test(TestBlueNoiseSpectrumThreads LABELS spectrum threads TIMEOUT 120)
bluenoise_add_test(TestBlueNoiseSpectrumThreadCount LABELS spectrum threads TIMEOUT 120)
bluenoise_add_test(TestBlueNoiseSpectrumExecutions LABELS spectrum LIBS VTK::ImagingCore VTK::FiltersCore)
bluenoise_add_test(TestBlueNoiseSpectrumAssumedGrid LABELS spectrum)
# Peak memory against the documented bytes a grid point; reads this process's
# resident high-water mark, so nothing runs beside it.
bluenoise_add_test(TestBlueNoiseSpectrumMemory LABELS "spectrum;memory")
set_tests_properties(TestBlueNoiseSpectrumMemory PROPERTIES SKIP_RETURN_CODE 125 RUN_SERIAL TRUE)
