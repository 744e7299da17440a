# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The plugin's NIfTI reader in pvpython, as File > Open uses it.

    pvpython TestNIfTIReaderPVPython.py --plugin BlueNoiseSampling.so [--mri ch2bet.nii.gz]

1. A small NIfTI-1 volume written here (5 x 4 x 3 int16 voxels, an sform that
   turns the axes and translates them), as .nii.gz and .nii: OpenDataFile()
   picks the reader from its ReaderFactory hint (BlueNoiseNIfTIReader), the
   reader factory lists "NIfTI volume (BlueNoise)" with *.nii.gz for the file
   dialog, the output has the dimensions, the world frame of the sform (every
   voxel where srow puts it, with its value) and the field-data array
   NIfTIFrame = sform, which the data information (the Information tab) lists.
   VoxelSpace = 1 gives the voxel frame.
2. A truncated .nii.gz (its header intact): OpenDataFile still picks the
   reader, the output is empty (the error goes to the output window), and the
   same reader reads a good file next.
3. The MRI volume of mricron-data when present: opened as .nii.gz, 181 x 217
   x 181 voxels in its sform, and sampled by the Error Diffusion Sampler.
"""
import argparse
import os
import tempfile

from paraview.simple import *  # noqa: F401,F403
from paraview import servermanager
from vtkmodules.util.numpy_support import vtk_to_numpy

from bluenoise_testing import check, finish
from nifti_testing import DIMS, PIXDIM, SROW, value, write_nifti


def frame_of(reader):
    data = reader.GetClientSideObject().GetOutputDataObject(0)
    array = data.GetFieldData().GetAbstractArray("NIfTIFrame")
    return array.GetValue(0) if array is not None and array.GetNumberOfValues() == 1 else None


def check_world(image, what):
    """Every voxel of the file at srow * (i, j, k, 1) in the output, with its value."""
    scalars = image.GetPointData().GetScalars()
    if not check(scalars is not None, "%s: point scalars" % what):
        return
    values = vtk_to_numpy(scalars)
    misplaced = wrong = 0
    for k in range(DIMS[2]):
        for j in range(DIMS[1]):
            for i in range(DIMS[0]):
                p = [SROW[r][0] * i + SROW[r][1] * j + SROW[r][2] * k + SROW[r][3] for r in range(3)]
                index = [0.0, 0.0, 0.0]
                image.TransformPhysicalPointToContinuousIndex(p, index)
                ijk = [int(round(x)) for x in index]
                if any(abs(x - n) > 1e-4 for x, n in zip(index, ijk)) or \
                        any(n < 0 or n >= d for n, d in zip(ijk, image.GetDimensions())):
                    misplaced += 1
                    continue
                wrong += int(values[image.ComputePointId(ijk)] != value(i, j, k))
    check(misplaced == 0 and wrong == 0,
          "%s: every voxel where the sform puts it (%d misplaced, %d with another value)" % (what, misplaced, wrong))


def open_and_check(path):
    reader = OpenDataFile(path)
    name = reader.GetXMLName() if reader is not None else None
    check(name == "BlueNoiseNIfTIReader", "%s: OpenDataFile picks BlueNoiseNIfTIReader (%s)"
          % (os.path.basename(path), name))
    if name != "BlueNoiseNIfTIReader":
        return None
    reader.UpdatePipeline()
    info = reader.GetDataInformation()
    dims = tuple(e[1] - e[0] + 1 for e in zip(info.GetExtent()[0::2], info.GetExtent()[1::2]))
    check(dims == DIMS, "%s: dimensions %s" % (os.path.basename(path), dims))
    check(frame_of(reader) == "sform", "%s: NIfTIFrame %r == 'sform'" % (os.path.basename(path), frame_of(reader)))
    check("NIfTIFrame" in reader.FieldData.keys(),
          "%s: the data information (Information tab) lists NIfTIFrame: %s"
          % (os.path.basename(path), list(reader.FieldData.keys())))
    check_world(reader.GetClientSideObject().GetOutputDataObject(0), os.path.basename(path))
    return reader


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--plugin", required=True)
    parser.add_argument("--mri", default="/usr/share/mricron/templates/ch2bet.nii.gz")
    args = parser.parse_args()
    if not check(os.path.exists(args.plugin), "plugin file %s exists" % args.plugin):
        finish()
    LoadPlugin(args.plugin, remote=False, ns=globals())

    with tempfile.TemporaryDirectory(prefix="bluenoise-nifti-pv-") as tmp:
        gz = write_nifti(os.path.join(tmp, "turned.nii.gz"))
        plain = write_nifti(os.path.join(tmp, "turned.nii"))

        # The file dialog's reader list (what File > Open offers).
        factory = servermanager.vtkSMProxyManager.GetProxyManager().GetReaderFactory()
        session = servermanager.ActiveConnection.Session
        types = factory.GetSupportedFileTypes(session)
        check("NIfTI volume (BlueNoise)" in types and "*.nii.gz" in types,
              "File > Open lists 'NIfTI volume (BlueNoise)' with *.nii.gz")
        check(factory.CanReadFile(gz, session) and factory.GetReaderName() == "BlueNoiseNIfTIReader",
              "the reader factory opens .nii.gz with BlueNoiseNIfTIReader (%s)" % factory.GetReaderName())

        reader = open_and_check(gz)
        open_and_check(plain)
        if reader is not None:
            reader.VoxelSpace = 1
            reader.UpdatePipeline()
            image = reader.GetClientSideObject().GetOutputDataObject(0)
            check(frame_of(reader) == "voxel" and tuple(image.GetSpacing()) == PIXDIM
                  and tuple(image.GetOrigin()) == (0.0, 0.0, 0.0),
                  "VoxelSpace = 1: frame %r, origin %s, spacing %s"
                  % (frame_of(reader), image.GetOrigin(), image.GetSpacing()))

        # 2. A truncated file whose header is intact (the gzip stream cut 12 bytes
        # before its end): the factory still picks the reader, which says what is
        # wrong and gives an empty output, then reads a good file.
        cut = os.path.join(tmp, "cut.nii.gz")
        with open(gz, "rb") as src, open(cut, "wb") as dst:
            blob = src.read()
            dst.write(blob[: len(blob) - 12])
        bad = OpenDataFile(cut)
        check(bad is not None and bad.GetXMLName() == "BlueNoiseNIfTIReader", "cut.nii.gz: our reader")
        if bad is not None:
            print("(an error about cut.nii.gz follows: expected)", flush=True)
            bad.UpdatePipeline()
            check(bad.GetDataInformation().GetNumberOfPoints() == 0,
                  "cut.nii.gz: empty output (%d points)" % bad.GetDataInformation().GetNumberOfPoints())
            bad.FileName = gz
            bad.UpdatePipeline()
            check(bad.GetDataInformation().GetNumberOfPoints() == DIMS[0] * DIMS[1] * DIMS[2],
                  "the same reader then reads turned.nii.gz (%d points)" % bad.GetDataInformation().GetNumberOfPoints())
            Delete(bad)
        for proxy in list(GetSources().values()):
            Delete(proxy)

    # 3. The MRI volume, as a medical user opens it.
    if args.mri and os.path.exists(args.mri):
        mri = OpenDataFile(args.mri)
        check(mri is not None and mri.GetXMLName() == "BlueNoiseNIfTIReader",
              "%s: BlueNoiseNIfTIReader" % args.mri)
        if mri is not None:
            mri.UpdatePipeline()
            image = mri.GetClientSideObject().GetOutputDataObject(0)
            check(tuple(image.GetDimensions()) == (181, 217, 181), "MRI dimensions %s" % (image.GetDimensions(),))
            check(frame_of(mri) == "sform", "MRI frame %r" % frame_of(mri))
            s = ErrorDiffusionSampler(Input=mri, NumberOfPoints=2000)
            s.UpdatePipeline()
            points = s.GetClientSideObject().GetOutputDataObject(0)
            n = points.GetNumberOfPoints()
            b, ib = points.GetBounds(), image.GetBounds()
            check(n > 1000 and all(b[2 * a] >= ib[2 * a] - 2 and b[2 * a + 1] <= ib[2 * a + 1] + 2 for a in range(3)),
                  "MRI sampled: %d points inside the volume's world bounds" % n)
            Delete(s)
            Delete(mri)
    else:
        print("note: %s not found: the MRI part is skipped" % args.mri)
    finish()


if __name__ == "__main__":
    main()
