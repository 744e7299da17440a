# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
# The volume loading of the programs (Apps/Common, BlueNoiseApps) on arbitrary
# bytes; seeds in corpus/FuzzVolumeLoader/ (a .vti with ascii data, a NIfTI-1
# header and body, a NRRD with inline raw data, a MetaImage with LOCAL data,
# and the inputs that crashed or hung vtkNrrdReader or vtkNIFTIImageReader
# before the checks caught them).
# Runs need LSAN_OPTIONS=suppressions=Testing/Fuzz/VolumeLoader.lsan.supp: VTK
# 9.2's XML reader leaks an iterator when an array fails to read (a fuzzer
# finding outside the project's code). Included by Testing/Fuzz/CMakeLists.txt,
# which defines bluenoise_add_fuzzer.
if (NOT TARGET BlueNoiseApps)
  return ()
endif ()
bluenoise_fuzz_instrument(BlueNoiseApps)
bluenoise_add_fuzzer(FuzzVolumeLoader SOURCES FuzzVolumeLoader.cxx LIBRARIES BlueNoiseApps)
set_tests_properties(FuzzVolumeLoader PROPERTIES
  ENVIRONMENT "LSAN_OPTIONS=suppressions=${CMAKE_CURRENT_LIST_DIR}/VolumeLoader.lsan.supp")
