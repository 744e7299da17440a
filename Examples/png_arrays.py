# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""PNG files as numpy arrays (row 0 at the top), through VTK's PNG reader and writer.

A module of its own, without ParaView, so that both pbvr_compare.py (under
pvbatch, which finds it next to the script) and the test that checks its
pictures (Testing/Applications/TestPBVR.py, in VTK's plain Python, which
cannot import pbvr_compare.py: that needs paraview.simple) read PNGs the same
way.
"""
import numpy as np

from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData
from vtkmodules.vtkIOImage import vtkPNGReader, vtkPNGWriter


def read_png(path):
    """(h, w, c) float array in [0, 1], row 0 at the top."""
    r = vtkPNGReader()
    r.SetFileName(path)
    r.Update()
    img = r.GetOutput()
    w, h, _ = img.GetDimensions()
    a = vtk_to_numpy(img.GetPointData().GetScalars()).reshape(h, w, -1)
    return a[::-1].astype(np.float64) / 255.0


def write_png(path, rgb):
    """rgb: (h, w, 3) float in [0, 1], row 0 at the top."""
    h, w, _ = rgb.shape
    data = np.ascontiguousarray((np.clip(rgb, 0, 1) * 255 + 0.5).astype(np.uint8)[::-1].reshape(-1, 3))
    img = vtkImageData()
    img.SetDimensions(w, h, 1)
    arr = numpy_to_vtk(data, deep=1)
    arr.SetName("rgb")
    img.GetPointData().SetScalars(arr)
    wr = vtkPNGWriter()
    wr.SetFileName(path)
    wr.SetInputData(img)
    wr.Write()
