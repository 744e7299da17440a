# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
# The main job as a user sees it: bluenoise-sample on Data/brain-small.vti with
# 20000 points, under xvfb-run when there is one (else with --no-pictures),
# then checks of its exit status, its files (samples.vtp, spectrum.csv,
# metrics.csv, samples.png, spectrum.png), the pictures (CheckMainJobPicture)
# and the summary line; see RunMainJobTest.cmake.
add_executable(CheckMainJobPicture CheckMainJobPicture.cxx)
target_link_libraries(CheckMainJobPicture PRIVATE
  VTK::CommonCore VTK::CommonDataModel VTK::IOImage)

find_program(BLUENOISE_XVFB_RUN NAMES xvfb-run DOC "xvfb-run, for the MainJob test's pictures")
add_test(NAME MainJob
  COMMAND "${CMAKE_COMMAND}"
    "-DPROGRAM=$<TARGET_FILE:bluenoise-sample>"
    "-DCHECKER=$<TARGET_FILE:CheckMainJobPicture>"
    "-DINPUT=${CMAKE_SOURCE_DIR}/Data/brain-small.vti"
    "-DOUTPUT=${CMAKE_BINARY_DIR}/mainjob"
    "-DPOINTS=20000"
    "-DXVFB_RUN=${BLUENOISE_XVFB_RUN}"
    -P "${CMAKE_CURRENT_SOURCE_DIR}/RunMainJobTest.cmake")
set_tests_properties(MainJob PROPERTIES LABELS "mainjob" TIMEOUT 600 RESOURCE_LOCK xvfb)
