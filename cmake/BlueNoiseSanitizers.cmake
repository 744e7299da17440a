# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
# Sanitizer and fuzzer builds (scripts/sanitize.sh runs them; scripts/test.sh in CI).
#
#   BLUENOISE_SANITIZE  "address;undefined" or "thread" (empty: none). Every target of
#                       the project (module, programs, tests) is compiled and linked with
#                       -fsanitize=<list> -fno-omit-frame-pointer; UBSan stops at the first
#                       report (-fno-sanitize-recover=undefined).
#   BLUENOISE_FUZZ      the libFuzzer targets of Testing/Fuzz (clang only); implies
#                       BLUENOISE_SANITIZE=address;undefined when that is empty.
#
# The ASan runtime is a shared library in both compilers' builds here (GCC's default;
# clang with -shared-libasan), so the C++ programs and a Python interpreter that
# preloads it (BLUENOISE_SANITIZER_RUNTIME; scripts/sanitize.sh sets LD_PRELOAD for
# the tests that start Python) use one and the same runtime.
set(BLUENOISE_SANITIZE "" CACHE STRING
  "Sanitizers for every target: address;undefined, thread, or empty for none")
option(BLUENOISE_FUZZ "Build the libFuzzer targets in Testing/Fuzz (clang only)" OFF)

set(BLUENOISE_SANITIZER_RUNTIME "")
if (BLUENOISE_FUZZ)
  if (NOT CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    message(FATAL_ERROR "BLUENOISE_FUZZ needs clang (libFuzzer): configure with "
      "-DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++")
  endif ()
  if (NOT BLUENOISE_SANITIZE)
    set(BLUENOISE_SANITIZE "address;undefined" CACHE STRING
      "Sanitizers for every target: address;undefined, thread, or empty for none" FORCE)
  endif ()
endif ()
if (NOT BLUENOISE_SANITIZE)
  return ()
endif ()

if ("thread" IN_LIST BLUENOISE_SANITIZE AND "address" IN_LIST BLUENOISE_SANITIZE)
  message(FATAL_ERROR "BLUENOISE_SANITIZE: thread and address cannot be combined")
endif ()
list(JOIN BLUENOISE_SANITIZE "," _bluenoise_sanitizers)
set(_bluenoise_sanitizer_flags "-fsanitize=${_bluenoise_sanitizers}" -fno-omit-frame-pointer)
if ("undefined" IN_LIST BLUENOISE_SANITIZE)
  list(APPEND _bluenoise_sanitizer_flags -fno-sanitize-recover=undefined)
endif ()
add_compile_options(${_bluenoise_sanitizer_flags})
add_link_options(${_bluenoise_sanitizer_flags})

if ("address" IN_LIST BLUENOISE_SANITIZE)
  if (CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    set(_bluenoise_asan_name "libclang_rt.asan-${CMAKE_SYSTEM_PROCESSOR}.so")
  else ()
    set(_bluenoise_asan_name "libasan.so")
  endif ()
  execute_process(COMMAND "${CMAKE_CXX_COMPILER}" "-print-file-name=${_bluenoise_asan_name}"
    OUTPUT_VARIABLE BLUENOISE_SANITIZER_RUNTIME OUTPUT_STRIP_TRAILING_WHITESPACE)
  if (NOT IS_ABSOLUTE "${BLUENOISE_SANITIZER_RUNTIME}")
    message(FATAL_ERROR "BLUENOISE_SANITIZE: ${CMAKE_CXX_COMPILER} does not know ${_bluenoise_asan_name}")
  endif ()
  if (CMAKE_CXX_COMPILER_ID MATCHES "Clang")
    # clang links a static runtime into each program by default; a Python process
    # needs the shared one, and two runtimes in one process do not work. The
    # libraries take the runtime from the process that loads them (no NEEDED
    # entry), so the fuzzers can keep clang's static one (see Testing/Fuzz).
    get_filename_component(_bluenoise_asan_dir "${BLUENOISE_SANITIZER_RUNTIME}" DIRECTORY)
    add_link_options("$<$<STREQUAL:$<TARGET_PROPERTY:TYPE>,EXECUTABLE>:-shared-libasan>"
      "-Wl,-rpath,${_bluenoise_asan_dir}")
  endif ()
endif ()
# What a program built elsewhere against this build's libraries links with
# (Testing/Install's example).
string(REPLACE ";" " " BLUENOISE_SANITIZER_EXE_LINKER_FLAGS "${_bluenoise_sanitizer_flags}")
if (_bluenoise_asan_dir)
  string(APPEND BLUENOISE_SANITIZER_EXE_LINKER_FLAGS
    " -shared-libasan -Wl,-rpath,${_bluenoise_asan_dir}")
endif ()
message(STATUS "BlueNoise: sanitizers ${_bluenoise_sanitizers}"
  " (runtime for Python: ${BLUENOISE_SANITIZER_RUNTIME})")

