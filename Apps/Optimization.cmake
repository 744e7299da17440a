# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
# bluenoise-optimize: the parameter search of the paper (section 4.2).
add_executable(bluenoise-optimize bluenoise_optimize.cxx)
target_link_libraries(bluenoise-optimize PRIVATE BlueNoise::FiltersBlueNoise Threads::Threads)
install(TARGETS bluenoise-optimize RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")

# bluenoise-quality: the quality report of the parameter sets (Testing/QualityReport.md).
add_executable(bluenoise-quality bluenoise_quality.cxx)
target_link_libraries(bluenoise-quality PRIVATE BlueNoise::FiltersBlueNoise)
