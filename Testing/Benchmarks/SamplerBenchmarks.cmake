# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
# The smoke run (CTest): the smallest cases.
bluenoise_add_benchmark(BenchmarkErrorDiffusionSampler
  SMOKE "^BM_Kernel/L:256/g255:8$|^BM_Relaxation/L:256/g255:8$|^BM_Filter/L:256/g255:8/float:0/busy:0/thread:1")
# The tight loop as a library that pvpython_update_pipeline.py loads (ctypes),
# to time the baseline in pvpython's own process.
add_library(BlueNoiseTightScan MODULE BlueNoiseTightScanLibrary.cxx)
target_link_libraries(BlueNoiseTightScan PRIVATE BlueNoise::FiltersBlueNoise)
set_target_properties(BlueNoiseTightScan PROPERTIES CXX_VISIBILITY_PRESET hidden)
