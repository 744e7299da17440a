# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
# Python wrapping of the module: `from bluenoise import vtkErrorDiffusionSampler`
# works in any Python that has the VTK the module was built against (pvpython,
# or Debian's python3 with python3-paraview's vtkmodules).
if (DEFINED VTK_PYTHONPATH)
  set(BLUENOISE_PYTHON_DESTINATION "${VTK_PYTHONPATH}")
else ()
  vtk_module_python_default_destination(BLUENOISE_PYTHON_DESTINATION)
endif ()

vtk_module_wrap_python(
  MODULES             ${bluenoise_modules}
  TARGET              BlueNoise::Python
  WRAPPED_MODULES     bluenoise_wrapped_modules
  INSTALL_EXPORT      BlueNoiseSamplingPython
  PYTHON_PACKAGE      "bluenoise"
  MODULE_DESTINATION  "${BLUENOISE_PYTHON_DESTINATION}"
  CMAKE_DESTINATION   "${BLUENOISE_CMAKE_DESTINATION}"
  LIBRARY_DESTINATION "${CMAKE_INSTALL_LIBDIR}"
  BUILD_STATIC        OFF
  INSTALL_HEADERS     OFF)

# The package: the wrapped module plus an __init__ that re-exports its classes.
set(_bluenoise_package_dir "${CMAKE_BINARY_DIR}/${BLUENOISE_PYTHON_DESTINATION}/bluenoise")
configure_file("${CMAKE_CURRENT_LIST_DIR}/bluenoise__init__.py"
  "${_bluenoise_package_dir}/__init__.py" COPYONLY)
install(FILES "${_bluenoise_package_dir}/__init__.py"
  DESTINATION "${BLUENOISE_PYTHON_DESTINATION}/bluenoise")
set(BLUENOISE_PYTHONPATH "${CMAKE_BINARY_DIR}/${BLUENOISE_PYTHON_DESTINATION}")
