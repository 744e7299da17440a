# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
# vtkBlueNoiseNIfTIReader: small NIfTI files the tests write (and the MRI volume
# of mricron-data when present), placed in their world frame and compared with
# the main job's loader (BlueNoiseApps); bad files give an error and an empty output.
bluenoise_add_test(TestBlueNoiseNIfTIReader LABELS reader
  LIBS BlueNoiseApps VTK::IOImage VTK::zlib)
bluenoise_add_test(TestBlueNoiseNIfTIReaderBadFiles LABELS reader LIBS VTK::zlib)
