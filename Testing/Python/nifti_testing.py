# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Small NIfTI-1 volumes written by the Python tests themselves (no data files):
a 348-byte little-endian header with 4 bytes of extension flags, then int16
voxels with value(i, j, k) = i + 10 j + 100 k."""
import gzip
import struct

DIMS = (5, 4, 3)
PIXDIM = (1.5, 2.0, 2.5)
# The sform: x = -2 j + 10, y = 1.5 i - 20, z = 2.5 k + 5 (a turn about z, a translation).
SROW = ((0.0, -2.0, 0.0, 10.0), (1.5, 0.0, 0.0, -20.0), (0.0, 0.0, 2.5, 5.0))


def value(i, j, k):
    return i + 10 * j + 100 * k


def nifti_bytes(sform_code=1):
    h = bytearray(352)
    struct.pack_into("<i", h, 0, 348)
    struct.pack_into("<8h", h, 40, 3, DIMS[0], DIMS[1], DIMS[2], 1, 1, 1, 1)
    struct.pack_into("<hh", h, 70, 4, 16)  # DT_INT16, bitpix
    struct.pack_into("<8f", h, 76, 1.0, PIXDIM[0], PIXDIM[1], PIXDIM[2], 1, 1, 1, 1)
    struct.pack_into("<ff", h, 108, 352.0, 1.0)  # vox_offset, scl_slope
    struct.pack_into("<hh", h, 252, 0, sform_code)  # qform_code, sform_code
    struct.pack_into("<12f", h, 280, *[v for row in SROW for v in row])
    h[344:348] = b"n+1\0"
    body = bytearray()
    for k in range(DIMS[2]):
        for j in range(DIMS[1]):
            for i in range(DIMS[0]):
                body += struct.pack("<h", value(i, j, k))
    return bytes(h + body)


def write_nifti(path, sform_code=1):
    """Writes the volume to `path`, gzipped when it ends in .gz; returns the path."""
    data = nifti_bytes(sform_code)
    opener = gzip.open if path.endswith(".gz") else open
    with opener(path, "wb") as f:
        f.write(data)
    return path
