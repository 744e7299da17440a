# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
# The smoke run (CTest): the smallest cases.
bluenoise_add_benchmark(BenchmarkSpectrum SMOKE "/(64|128)/1/")
# The FFTW 3D plan with FFTW threads is the baseline the kernel's transform is
# measured against (libfftw3_threads ships with Debian's libfftw3-dev; it has
# no pkg-config file of its own).
find_library(BLUENOISE_FFTW3_THREADS_LIBRARY NAMES fftw3_threads HINTS ${FFTW3_LIBRARY_DIRS})
if (BLUENOISE_FFTW3_THREADS_LIBRARY)
  target_link_libraries(BenchmarkSpectrum PRIVATE
    "${BLUENOISE_FFTW3_THREADS_LIBRARY}" PkgConfig::FFTW3 Threads::Threads)
  target_compile_definitions(BenchmarkSpectrum PRIVATE BLUENOISE_HAVE_FFTW3_THREADS)
else ()
  message(STATUS "libfftw3_threads not found: BenchmarkSpectrum runs without its FFTW 3D baseline")
endif ()
