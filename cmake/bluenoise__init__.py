# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Blue-noise sampling of volumes by 3D error diffusion, and a 3D blue-noise spectrum.

vtkErrorDiffusionSampler: vtkImageData in, blue-noise sample points (vtkPolyData) out.
vtkBlueNoiseSpectrum: points or image in, radially averaged power spectrum and metrics out.
vtkBlueNoiseNIfTIReader: a NIfTI file (.nii, .nii.gz) in, vtkImageData in its sform or qform world frame out.
"""
from .vtkFiltersBlueNoise import *  # noqa: F401,F403
