# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
# bluenoise-optimize: the parameter search of the paper (section 4.2).
bluenoise_program(bluenoise-optimize SOURCES bluenoise_optimize.cxx LIBRARIES Threads::Threads)

# bluenoise-quality: the quality report of the parameter sets (Testing/QualityReport.md).
bluenoise_program(bluenoise-quality SOURCES bluenoise_quality.cxx)
