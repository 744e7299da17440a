# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
# Installs a CMake package so a VTK application can
#   find_package(BlueNoiseSampling REQUIRED)
#   target_link_libraries(app PRIVATE BlueNoise::FiltersBlueNoise)
include(CMakePackageConfigHelpers)

set(_bluenoise_config_dir "${CMAKE_BINARY_DIR}/${BLUENOISE_CMAKE_DESTINATION}")
configure_file(
  "${CMAKE_CURRENT_LIST_DIR}/BlueNoiseSamplingConfig.cmake.in"
  "${_bluenoise_config_dir}/BlueNoiseSamplingConfig.cmake"
  @ONLY)
write_basic_package_version_file(
  "${_bluenoise_config_dir}/BlueNoiseSamplingConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}"
  COMPATIBILITY SameMajorVersion)
install(
  FILES
    "${_bluenoise_config_dir}/BlueNoiseSamplingConfig.cmake"
    "${_bluenoise_config_dir}/BlueNoiseSamplingConfigVersion.cmake"
  DESTINATION "${BLUENOISE_CMAKE_DESTINATION}")
