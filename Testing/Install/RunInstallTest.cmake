# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
# Installs the build tree to a scratch prefix and uses it as a user would.
#
#   cmake -DBUILD_DIR=... -DPREFIX=... -DWORK_DIR=... -DEXAMPLE_SOURCE=...
#         -DLIBDIR=lib -DINCLUDEDIR=include -DGENERATOR=Ninja [-DMAKE_PROGRAM=...]
#         [-DCXX_COMPILER=...] [-DBUILD_TYPE=Release] [-DEXE_LINKER_FLAGS=...]
#         [-DPYTHON=/usr/bin/python3 -DPYTHON_DESTINATION=lib/python3/dist-packages]
#         [-DPVPYTHON=/usr/bin/pvpython -DPLUGIN_DESTINATION=lib/paraview-5.11/plugins]
#         [-DBINDIR=bin -DPROGRAMS=name|name|... -DVOLUME=small.vti]
#         -P RunInstallTest.cmake
#
# 1. cmake --install BUILD_DIR --prefix PREFIX, and the expected files are there;
# 2. Example/ (find_package(BlueNoiseSampling REQUIRED), links
#    BlueNoise::FiltersBlueNoise) configures against PREFIX only, builds and runs,
#    and loads the installed library (not the build tree's);
# 3. with PYTHON: `import bluenoise` from PREFIX works and samples;
# 4. with PVPYTHON: the installed plugin loads in pvpython and samples;
# 5. with PROGRAMS: each is in BINDIR, loads the installed library and prints
#    its --help with LD_LIBRARY_PATH holding only VTK_LIBRARY_DIR (this
#    project's library comes from the RUNPATH, relative to the binary);
#    bluenoise-sample samples VOLUME from the install tree.
# Any failure stops with a message saying which step failed.
cmake_minimum_required(VERSION 3.13)

foreach (var IN ITEMS BUILD_DIR PREFIX WORK_DIR EXAMPLE_SOURCE LIBDIR INCLUDEDIR GENERATOR)
  if (NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "RunInstallTest.cmake: ${var} is not set")
  endif ()
endforeach ()

function (run step)
  execute_process(COMMAND ${ARGN}
    RESULT_VARIABLE result
    OUTPUT_VARIABLE output
    ERROR_VARIABLE output)
  message(STATUS "[${step}] ${output}")
  if (NOT result EQUAL 0)
    message(FATAL_ERROR "[${step}] FAILED (exit ${result}): ${ARGN}")
  endif ()
  set(run_output "${output}" PARENT_SCOPE)
endfunction ()

function (expect_file path)
  if (NOT EXISTS "${PREFIX}/${path}")
    message(FATAL_ERROR "[install] missing ${PREFIX}/${path}")
  endif ()
  message(STATUS "[install] ok: ${path}")
endfunction ()

file(REMOVE_RECURSE "${PREFIX}" "${WORK_DIR}")
file(MAKE_DIRECTORY "${WORK_DIR}")

# --- 1. install --------------------------------------------------------------
run(install "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${PREFIX}")
set(config_dir "${PREFIX}/${LIBDIR}/cmake/BlueNoiseSampling")
foreach (file IN ITEMS
    "${LIBDIR}/cmake/BlueNoiseSampling/BlueNoiseSamplingConfig.cmake"
    "${LIBDIR}/cmake/BlueNoiseSampling/BlueNoiseSamplingConfigVersion.cmake"
    "${LIBDIR}/cmake/BlueNoiseSampling/BlueNoiseSampling-targets.cmake"
    "${LIBDIR}/cmake/BlueNoiseSampling/BlueNoiseSampling-vtk-module-properties.cmake"
    "${INCLUDEDIR}/BlueNoiseSampling/vtkErrorDiffusionSampler.h"
    "${INCLUDEDIR}/BlueNoiseSampling/vtkBlueNoiseSpectrum.h"
    "${INCLUDEDIR}/BlueNoiseSampling/vtkFiltersBlueNoiseModule.h"
    "${LIBDIR}/libvtkFiltersBlueNoise.so")
  expect_file("${file}")
endforeach ()
# The package must not point back into the build tree.
file(GLOB config_files "${config_dir}/*.cmake")
foreach (file IN LISTS config_files)
  file(READ "${file}" content)
  string(FIND "${content}" "${BUILD_DIR}/" at)
  if (NOT at EQUAL -1)
    message(FATAL_ERROR "[install] ${file} refers to the build tree ${BUILD_DIR}")
  endif ()
endforeach ()

# --- 2. the example ------------------------------------------------------------
set(example_build "${WORK_DIR}/build")
set(configure_args
  -S "${EXAMPLE_SOURCE}" -B "${example_build}" -G "${GENERATOR}"
  "-DBlueNoiseSampling_DIR=${config_dir}")
if (MAKE_PROGRAM)
  list(APPEND configure_args "-DCMAKE_MAKE_PROGRAM=${MAKE_PROGRAM}")
endif ()
if (CXX_COMPILER)
  list(APPEND configure_args "-DCMAKE_CXX_COMPILER=${CXX_COMPILER}")
endif ()
if (BUILD_TYPE)
  list(APPEND configure_args "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}")
endif ()
if (EXE_LINKER_FLAGS)
  list(APPEND configure_args "-DCMAKE_EXE_LINKER_FLAGS=${EXE_LINKER_FLAGS}")
endif ()
# No VTK_DIR: the package has to find the VTK it was built against by itself.
run(configure "${CMAKE_COMMAND}" ${configure_args})
run(build "${CMAKE_COMMAND}" --build "${example_build}")
set(example "${example_build}/bluenoise_install_example")
run(run "${example}")
if (NOT run_output MATCHES "passed")
  message(FATAL_ERROR "[run] the example did not report success")
endif ()

# Binaries using the installed module must load the installed library, not the
# build tree's (which would hide a broken install once the build tree is gone).
find_program(LDD ldd)
function (expect_installed_library binary)
  if (NOT LDD)
    return ()
  endif ()
  run(ldd "${LDD}" "${binary}")
  string(REGEX MATCH "libvtkFiltersBlueNoise[^\n]*=> ([^ \n]+)" line "${run_output}")
  set(loaded "${CMAKE_MATCH_1}")
  get_filename_component(loaded_real "${loaded}" REALPATH)
  get_filename_component(prefix_real "${PREFIX}" REALPATH)
  string(FIND "${loaded_real}" "${prefix_real}/" at)
  if (NOT at EQUAL 0)
    message(FATAL_ERROR "[ldd] ${binary} loads libvtkFiltersBlueNoise from '${loaded}', "
      "not from ${PREFIX}/${LIBDIR}")
  endif ()
  message(STATUS "[ldd] ok: ${binary} -> ${loaded}")
endfunction ()
expect_installed_library("${example}")

# --- 3. the Python package ------------------------------------------------------
if (PYTHON AND PYTHON_DESTINATION)
  expect_file("${PYTHON_DESTINATION}/bluenoise/__init__.py")
  file(GLOB wrapped "${PREFIX}/${PYTHON_DESTINATION}/bluenoise/vtkFiltersBlueNoise*.so")
  if (NOT wrapped)
    message(FATAL_ERROR "[install] no bluenoise/vtkFiltersBlueNoise*.so under ${PREFIX}/${PYTHON_DESTINATION}")
  endif ()
  set(script "${WORK_DIR}/import_bluenoise.py")
  file(WRITE "${script}" [=[
import sys
import bluenoise
from bluenoise import vtkErrorDiffusionSampler
from vtkmodules.vtkImagingCore import vtkRTAnalyticSource
prefix = sys.argv[1]
assert bluenoise.__file__.startswith(prefix), "bluenoise imported from %s, not %s" % (bluenoise.__file__, prefix)
source = vtkRTAnalyticSource()
sampler = vtkErrorDiffusionSampler()
sampler.SetInputConnection(source.GetOutputPort())
sampler.SetDensityScale(0.2)
sampler.Update()
n = sampler.GetOutput().GetNumberOfPoints()
assert n > 100, "only %d points" % n
print("python: %d points from %s" % (n, bluenoise.__file__))
]=])
  foreach (module IN LISTS wrapped)
    expect_installed_library("${module}")
  endforeach ()
  get_filename_component(prefix_real "${PREFIX}" REALPATH)
  run(python "${CMAKE_COMMAND}" -E env "PYTHONPATH=${PREFIX}/${PYTHON_DESTINATION}"
    "${PYTHON}" "${script}" "${prefix_real}")
endif ()

# --- 4. the ParaView plugin ---------------------------------------------------------
if (PVPYTHON AND PLUGIN_DESTINATION)
  set(plugin "${PLUGIN_DESTINATION}/BlueNoiseSampling/BlueNoiseSampling.so")
  expect_file("${plugin}")
  set(script "${WORK_DIR}/load_plugin.py")
  file(WRITE "${script}" [=[
import sys
from paraview.simple import *
LoadPlugin(sys.argv[1], remote=False, ns=globals())
sampler = ErrorDiffusionSampler(Input=Wavelet(), DensityScale=0.2)
sampler.UpdatePipeline()
n = sampler.GetDataInformation().GetNumberOfPoints()
assert n > 100, "only %d points" % n
print("pvpython: %d points with the installed plugin" % n)
]=])
  expect_installed_library("${PREFIX}/${plugin}")
  run(plugin "${PVPYTHON}" "${script}" "${PREFIX}/${plugin}")
endif ()

# --- 5. the programs -------------------------------------------------------------
if (PROGRAMS)
  string(REPLACE "|" ";" programs "${PROGRAMS}")
  foreach (program IN LISTS programs)
    set(binary "${PREFIX}/${BINDIR}/${program}")
    expect_file("${BINDIR}/${program}")
    expect_installed_library("${binary}")
    run(${program} "${CMAKE_COMMAND}" -E env "LD_LIBRARY_PATH=${VTK_LIBRARY_DIR}" "${binary}" --help)
    if (NOT run_output MATCHES "Usage: ${program}")
      message(FATAL_ERROR "[${program}] --help printed no usage: ${run_output}")
    endif ()
  endforeach ()
  if (VOLUME AND "bluenoise-sample" IN_LIST programs)
    run(sample "${CMAKE_COMMAND}" -E env "LD_LIBRARY_PATH=${VTK_LIBRARY_DIR}"
      "${PREFIX}/${BINDIR}/bluenoise-sample" "${VOLUME}" --output "${WORK_DIR}/sample"
      --points 500 --spectrum-grid 16 --no-pictures)
    if (NOT run_output MATCHES "points=[0-9]+ expected=500 ")
      message(FATAL_ERROR "[sample] no summary with expected=500: ${run_output}")
    endif ()
  endif ()
endif ()

message(STATUS "install test passed")
