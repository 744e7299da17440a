# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Regression tests of the programs' handling of files and options.

Every case generates its input files (plain Python: no VTK needed), runs a
program and checks its exit status, its message and what it wrote:

  python3 TestProgramInputs.py --sample BIN --optimize BIN --quality BIN \
      --work DIR --case NAME        (--list prints the case names)

Hostile files must fail with status 1, a message naming the file and the
problem, within seconds (a timeout of 20 s fails the case) and without
touching the output folder; bad options fail with status 2 and a message
naming the option and the value.
"""
import argparse
import gzip
import math
import os
import re
import shutil
import struct
import subprocess
import sys

CASES = {}


def case(function):
    CASES[function.__name__] = function
    return function


class Failure(Exception):
    pass


def check(condition, message):
    if not condition:
        raise Failure(message)


# --- generated files ------------------------------------------------------------
def nifti_header(dims, pixdim=(1.0, 1.0, 1.0), vox_offset=352.0, datatype=2, bitpix=8,
                 sform=None, qform=None):
    """A NIfTI-1 header (348 bytes + 4 extension bytes) for a single .nii file.
    sform: 3 rows of 4 (srow_x, _y, _z); qform: (b, c, d, qx, qy, qz)."""
    h = bytearray(352)
    struct.pack_into('<i', h, 0, 348)
    d = [len(dims)] + list(dims) + [1] * (7 - len(dims))
    struct.pack_into('<8h', h, 40, *d)
    struct.pack_into('<hh', h, 70, datatype, bitpix)
    struct.pack_into('<8f', h, 76, 1.0, *(list(pixdim) + [1.0] * (7 - len(pixdim))))
    struct.pack_into('<f', h, 108, vox_offset)
    if qform is not None:
        struct.pack_into('<h', h, 252, 1)  # qform_code: scanner
        struct.pack_into('<6f', h, 256, *qform)
    if sform is not None:
        struct.pack_into('<h', h, 254, 2)  # sform_code: aligned
        for r, row in enumerate(sform):
            struct.pack_into('<4f', h, 280 + 16 * r, *row)
    h[344:348] = b'n+1\0'
    return bytes(h)


def nifti2_header(dims, vox_offset=544):
    h = bytearray(544)
    struct.pack_into('<i', h, 0, 540)
    h[4:12] = b'n+2\0\r\n\x1a\n'
    struct.pack_into('<hh', h, 12, 2, 8)
    struct.pack_into('<8q', h, 16, len(dims), *(list(dims) + [1] * (7 - len(dims))))
    struct.pack_into('<8d', h, 104, *([1.0] * 8))
    struct.pack_into('<q', h, 168, vox_offset)
    return bytes(h)


def ramp(n):
    """n bytes of a ramp, so that the density varies."""
    return bytes((7 * i) % 251 for i in range(n))


def write(path, data, compress=False):
    opener = gzip.open if compress else open
    with opener(path, 'wb') as f:
        f.write(data)
    return path


def metaimage(path, dims, data_file, element='MET_UCHAR', spacing=(1, 1, 1), big_endian=False):
    with open(path, 'w') as f:
        f.write('ObjectType = Image\nNDims = 3\n')
        if big_endian:
            f.write('BinaryDataByteOrderMSB = True\n')
        f.write('DimSize = %s\n' % ' '.join(str(d) for d in dims))
        f.write('ElementSpacing = %s\n' % ' '.join(str(s) for s in spacing))
        f.write('ElementType = %s\nElementDataFile = %s\n' % (element, data_file))
    return path


def vti_ascii(path, dims, arrays):
    """arrays: (type, name, values as text) in point data, ascii format."""
    extent = ' '.join('0 %d' % (d - 1) for d in dims)
    with open(path, 'w') as f:
        f.write('<?xml version="1.0"?>\n<VTKFile type="ImageData" version="1.0" '
                'byte_order="LittleEndian" header_type="UInt64">\n'
                '<ImageData WholeExtent="%s" Origin="0 0 0" Spacing="1 1 1">\n'
                '<Piece Extent="%s"><PointData>\n' % (extent, extent))
        for kind, name, text in arrays:
            f.write('<DataArray type="%s" Name="%s" format="ascii">%s</DataArray>\n'
                    % (kind, name, text))
        f.write('</PointData><CellData/></Piece></ImageData></VTKFile>\n')
    return path


def vti_raw_appended(path, dims, data):
    """A VTI whose one uint8 point array is raw appended data (streamable)."""
    extent = ' '.join('0 %d' % (d - 1) for d in dims)
    with open(path, 'wb') as f:
        f.write(('<?xml version="1.0"?>\n<VTKFile type="ImageData" version="1.0" '
                 'byte_order="LittleEndian" header_type="UInt64">\n'
                 '<ImageData WholeExtent="%s" Origin="0 0 0" Spacing="1 1 1">\n'
                 '<Piece Extent="%s"><PointData Scalars="v">\n'
                 '<DataArray type="UInt8" Name="v" format="appended" offset="0"/>\n'
                 '</PointData><CellData/></Piece></ImageData>\n'
                 '<AppendedData encoding="raw">\n_' % (extent, extent)).encode())
        f.write(struct.pack('<Q', len(data)) + data)
        f.write(b'\n</AppendedData>\n</VTKFile>\n')
    return path


# --- running the programs ---------------------------------------------------------
class Context:
    def __init__(self, args):
        self.args = args
        self.work = os.path.join(args.work, args.case)
        shutil.rmtree(self.work, ignore_errors=True)
        os.makedirs(self.work)
        self.out = os.path.join(self.work, 'out')

    def path(self, name):
        return os.path.join(self.work, name)

    def run(self, program, *arguments, timeout=20, environment=None):
        command = [getattr(self.args, program)] + [str(a) for a in arguments]
        print('running:', ' '.join(command), environment or '')
        env = dict(os.environ)
        env.pop('DISPLAY', None)
        env.update(environment or {})
        try:
            p = subprocess.run(command, cwd=self.work, capture_output=True, text=True,
                               timeout=timeout, env=env)
        except subprocess.TimeoutExpired:
            raise Failure('no answer within %d s' % timeout)
        print('exit %d\nstdout:\n%s\nstderr:\n%s' % (p.returncode, p.stdout, p.stderr))
        return p

    def sample(self, *arguments, **kw):
        return self.run('sample', '--no-pictures', '--spectrum-grid', 16,
                        '--output', self.out, *arguments, **kw)

    def summary(self, p):
        last = p.stdout.strip().splitlines()[-1]
        fields = dict(f.split('=', 1) for f in last.split())
        return fields


def expect_file_error(ctx, volume, *words, extra=()):
    """A hostile file: status 1, the file and each word in the message, no output."""
    p = ctx.sample(volume, *extra)
    check(p.returncode == 1, 'exit status %d, expected 1' % p.returncode)
    check(os.path.basename(volume) in p.stderr, 'the message does not name the file')
    for w in words:
        check(w in p.stderr, "the message does not say '%s'" % w)
    check(not os.path.exists(ctx.out), 'the output folder was created')
    check('Traceback' not in p.stderr and 'Segmentation' not in p.stderr, 'a crash')


def expect_option_error(ctx, program, arguments, *words):
    p = ctx.run(program, *arguments)
    check(p.returncode == 2, 'exit status %d, expected 2' % p.returncode)
    for w in words:
        check(w in p.stderr, "the message does not say '%s'" % w)
    check(p.stdout == '', 'something was printed on stdout')


# --- hostile files ------------------------------------------------------------------
@case
def empty_nifti(ctx):
    expect_file_error(ctx, write(ctx.path('empty.nii'), b''), 'shorter than a NIfTI header')


@case
def nifti_offset_beyond_file(ctx):
    path = write(ctx.path('offset.nii'), nifti_header((4, 4, 4), vox_offset=1.0e6) + ramp(64))
    expect_file_error(ctx, path, 'beyond the end')


@case
def nifti_short_body(ctx):
    path = write(ctx.path('short.nii'), nifti_header((64, 64, 64)) + ramp(1000))
    expect_file_error(ctx, path, '262144 bytes of data', 'has only 1000 bytes')


@case
def nifti_header_only(ctx):
    path = write(ctx.path('header.nii'), nifti_header((16, 16, 16)))
    expect_file_error(ctx, path, 'has only 0 bytes')


@case
def nifti_gz_lying_header(ctx):
    # 2048^3 voxels declared, 4 KiB of data.
    path = write(ctx.path('lying.nii.gz'), nifti_header((2048, 2048, 2048)) + ramp(4096),
                 compress=True)
    expect_file_error(ctx, path, '2048 x 2048 x 2048')


@case
def nifti_1e15_voxels(ctx):
    path = write(ctx.path('huge.nii'), nifti2_header((100000, 100000, 100000)) + ramp(4096))
    expect_file_error(ctx, path, '100000 x 100000 x 100000')


@case
def nifti_zero_dimension(ctx):
    expect_file_error(ctx, write(ctx.path('zero.nii'), nifti_header((4, 0, 4)) + ramp(64)),
                      'dimension y is 0')


@case
def nifti_negative_dimension(ctx):
    expect_file_error(ctx, write(ctx.path('neg.nii'), nifti_header((4, 4, -3)) + ramp(64)),
                      'dimension z is -3')


@case
def nifti_nan_spacing(ctx):
    path = write(ctx.path('nan.nii'), nifti_header((4, 4, 4), pixdim=(1, float('nan'), 1))
                 + ramp(64))
    expect_file_error(ctx, path, 'spacing y is nan')


@case
def nifti_sform_not_finite(ctx):
    # The world frame's matrix holds NaN, then infinity: points would too.
    for name, bad in (('nan', float('nan')), ('inf', float('inf'))):
        sform = [[1, 0, 0, bad], [0, 1, 0, 0], [0, 0, 1, 0]]
        path = write(ctx.path('sform_%s.nii' % name),
                     nifti_header((4, 4, 4), sform=sform) + ramp(64))
        expect_file_error(ctx, path, 'not finite', 'sform')
    # In voxel space the frame is not used: the same file samples.
    p = ctx.sample(path, '--voxel-space')
    check(p.returncode == 0, '--voxel-space: exit status %d' % p.returncode)


@case
def nifti_datatype_beyond_bitpix(ctx):
    # float64 voxels (datatype 64) with a bitpix of 8: the reader would allocate 8 bytes a voxel.
    path = write(ctx.path('bitpix.nii'), nifti_header((8, 8, 8), datatype=64, bitpix=8)
                 + ramp(512))
    expect_file_error(ctx, path, '4096 bytes of data', 'has only 512 bytes')


@case
def nifti_unknown_datatype(ctx):
    # VTK 9.2's vtkNIFTIImageReader looks the datatype up past the end of its
    # table when it does not know it, and crashes (found by the loader fuzzer):
    # a code NIfTI does not define, and NIfTI's float128, which VTK does not read.
    path = write(ctx.path('datatype.nii'), nifti_header((4, 4, 4), datatype=-27902) + ramp(64))
    expect_file_error(ctx, path, 'datatype -27902 is not one')
    path = write(ctx.path('float128.nii'), nifti_header((4, 4, 4), datatype=1536, bitpix=128)
                 + ramp(1024))
    expect_file_error(ctx, path, 'datatype 1536 is not one')


@case
def nifti_magic_against_sizeof_hdr(ctx):
    # A valid NIfTI-1 header carrying NIfTI-2's magic at byte 4: VTK's reader
    # goes by the magic and reads a NIfTI-2 header, whose datatype here is unknown.
    h = bytearray(nifti_header((4, 4, 4)))
    h[4:12] = b'n+2\0\r\n\x1a\n'
    struct.pack_into('<h', h, 12, -27902)
    path = write(ctx.path('magic.nii'), bytes(h) + ramp(256))
    expect_file_error(ctx, path, 'sizeof_hdr is 348 but the magic says NIfTI-2')


@case
def nifti_row_beyond_int(ctx):
    # Rows of 2^31 - 1 voxels of two uint8 components: VTK's reader counts a
    # row's bytes in an int.
    path = write(ctx.path('row.nii'), nifti2_header((2**31 - 1, 1, 1, 1, 2)) + ramp(64))
    expect_file_error(ctx, path, 'more than VTK\'s NIfTI reader reads')


@case
def nifti_header_image_pair(ctx):
    # A .hdr/.img pair (magic ni1, data from byte 0 of the .img) loads.
    h = bytearray(nifti_header((8, 8, 8), vox_offset=0.0)[:348])
    h[344:348] = b'ni1\0'
    write(ctx.path('pair.img'), ramp(512))
    p = ctx.sample(write(ctx.path('pair.hdr'), bytes(h)), '--points', 50)
    check(p.returncode == 0, 'exit status %d, expected 0' % p.returncode)
    check(ctx.summary(p)['voxels'] == '512', 'not the 512 voxels of the .img')
    # Its .img shorter than the header declares.
    shutil.rmtree(ctx.out)
    write(ctx.path('short.img'), ramp(500))
    expect_file_error(ctx, write(ctx.path('short.hdr'), bytes(h)), 'has only 500 bytes')


@case
def metaimage_missing_data_file(ctx):
    path = metaimage(ctx.path('missing.mhd'), (8, 8, 8), 'missing.raw')
    expect_file_error(ctx, path, 'missing.raw', 'No such file')


@case
def metaimage_short_data_file(ctx):
    write(ctx.path('short.raw'), ramp(100))
    path = metaimage(ctx.path('short.mhd'), (8, 8, 8), 'short.raw')
    expect_file_error(ctx, path, 'has only 100 bytes')


@case
def metaimage_negative_spacing(ctx):
    write(ctx.path('neg.raw'), ramp(512))
    path = metaimage(ctx.path('neg.mhd'), (8, 8, 8), 'neg.raw', spacing=(1, -2, 1))
    expect_file_error(ctx, path, 'spacing y is -2')


@case
def metaimage_bad_type(ctx):
    write(ctx.path('bad.raw'), ramp(512))
    path = metaimage(ctx.path('bad.mhd'), (8, 8, 8), 'bad.raw', element='MET_STRING')
    expect_file_error(ctx, path, "ElementType 'MET_STRING'")


@case
def nrrd_short_inline_data(ctx):
    header = b'NRRD0004\ntype: uint8\ndimension: 3\nsizes: 16 16 16\nencoding: raw\n\n'
    expect_file_error(ctx, write(ctx.path('short.nrrd'), header + ramp(300)),
                      'has only 300 bytes')


@case
def nrrd_sizes_beyond_dimension(ctx):
    # Three sizes for two dimensions (vtkNrrdReader crashed reading such).
    header = b'NRRD0004\ntype: uint8\ndimension: 2\nsizes: 12 8 4\nencoding: raw\n\n'
    expect_file_error(ctx, write(ctx.path('sizes.nrrd'), header + ramp(384)),
                      'does not have dimension (2) values')


@case
def nrrd_one_axis(ctx):
    # A valid one-axis NRRD: vtkNrrdReader (VTK 9.2) crashes on it (found by fuzzing).
    header = b'NRRD0004\ntype: uint8\ndimension: 1\nsizes: 122\nencoding: raw\n\n'
    expect_file_error(ctx, write(ctx.path('axis.nrrd'), header + ramp(122)),
                      "dimension is '1' (2 to 4 supported)")


@case
def vti_lying_extent(ctx):
    path = vti_ascii(ctx.path('lying.vti'), (4, 4, 4), [('UInt8', 'v', ' '.join(['1'] * 64))])
    text = open(path).read().replace('WholeExtent="0 3 0 3 0 3"',
                                     'WholeExtent="0 99999 0 99999 0 99999"')
    open(path, 'w').write(text)
    expect_file_error(ctx, path, '100000 x 100000 x 100000')


@case
def vti_lying_components(ctx):
    # 64 voxels of 10^8 components each, in a file of a few hundred bytes.
    path = vti_ascii(ctx.path('components.vti'), (4, 4, 4), [('Float64', 'v', '1 2 3')])
    text = open(path).read().replace('Name="v"', 'Name="v" NumberOfComponents="100000000"')
    open(path, 'w').write(text)
    expect_file_error(ctx, path, 'the arrays declare 51200000000 bytes')


@case
def vti_origin_direction_not_finite(ctx):
    for attribute, words in (('Origin="nan 0 0"', ("Origin 'nan 0 0' is not finite",)),
                             ('Origin="0 0 0" Direction="1 0 0 0 inf 0 0 0 1"',
                              ('Direction', 'is not finite'))):
        path = vti_ascii(ctx.path('frame.vti'), (4, 4, 4), [('UInt8', 'v', ' '.join(['9'] * 64))])
        text = open(path).read().replace('Origin="0 0 0"', attribute)
        open(path, 'w').write(text)
        expect_file_error(ctx, path, *words)


@case
def vti_string_first_array(ctx):
    # A string array first and no --array: a clear error, not a crash.
    strings = ' '.join(['97 0'] * 8)
    path = vti_ascii(ctx.path('strings.vti'), (2, 2, 2),
                     [('String', 'labels', strings), ('UInt8', 'v', '1 2 3 4 5 6 7 8')])
    expect_file_error(ctx, path, "'labels' is not numeric", '--array')


@case
def unknown_format(ctx):
    expect_file_error(ctx, write(ctx.path('volume.xyz'), ramp(10)), 'unknown volume format')


@case
def missing_file(ctx):
    expect_file_error(ctx, ctx.path('absent.nii'), 'No such file')


@case
def missing_input_before_display(ctx):
    # No DISPLAY and no --no-pictures: the missing volume is what is reported.
    p = ctx.run('sample', ctx.path('absent.nii'), '--output', ctx.out)
    check(p.returncode == 1 and 'absent.nii' in p.stderr, 'the missing input is not reported')
    check('render the pictures' not in p.stderr, 'the display was reported before the input')


@case
def missing_parameter_file(ctx):
    volume = write(ctx.path('v.nii'), nifti_header((8, 8, 8)) + ramp(512))
    p = ctx.sample(volume, '--parameters', ctx.path('absent-table.txt'))
    check(p.returncode == 1, 'exit status %d, expected 1' % p.returncode)
    check('--parameters' in p.stderr and 'absent-table.txt' in p.stderr,
          'the message does not name the option and the file')
    check(not os.path.exists(ctx.out), 'the output folder was created')


# --- options -------------------------------------------------------------------------
@case
def option_points_not_a_number(ctx):
    expect_option_error(ctx, 'sample', ['--points', 'abc'], '--points', "'abc'")


@case
def option_points_inf(ctx):
    expect_option_error(ctx, 'sample', ['--points', 'inf'], '--points', "'inf'")


@case
def option_points_negative(ctx):
    expect_option_error(ctx, 'sample', ['--points', '-5'], '--points', "'-5'", 'out of range')


@case
def option_points_overflow(ctx):
    expect_option_error(ctx, 'sample', ['--points', '99999999999999999999999'], '--points',
                        'overflows')


@case
def option_seed_not_a_number(ctx):
    expect_option_error(ctx, 'sample', ['--seed', 'x'], '--seed', "'x'")


@case
def option_seed_overflow(ctx):
    expect_option_error(ctx, 'sample', ['--seed', '99999999999'], '--seed', 'out of range')


@case
def option_scale_negative(ctx):
    expect_option_error(ctx, 'sample', ['--scale', '-1'], '--scale', "'-1'")


@case
def option_second_volume(ctx):
    expect_option_error(ctx, 'sample', ['a.nii', 'b.nii'], 'b.nii')


@case
def option_unknown(ctx):
    expect_option_error(ctx, 'sample', ['--pionts', '5'], '--pionts')


@case
def option_samples_extension(ctx):
    expect_option_error(ctx, 'sample', ['--samples', 'points.txt'], '--samples', 'points.txt')


@case
def option_optimize_levels(ctx):
    expect_option_error(ctx, 'optimize', ['--levels', '1,abc'], '--levels', "'abc'")


@case
def optimize_small_cube(ctx):
    # A cube too small to crop 8 voxels off each face: the table says the interior
    # figures were not measured (they used to read T=0).
    table = ctx.path('table.txt')
    p = ctx.run('optimize', '--size', '12', '--seeds', '1', '--evaluations', '3', '--levels', '8',
                '--output', table, timeout=60)
    check(p.returncode == 0, 'exit status %d' % p.returncode)
    text = open(table).read() if os.path.exists(table) else ''
    check('interior not measured (a cube of 12 voxels less 8 at each face leaves less than 4)'
          in text and 'interior T=' not in text, 'the table: %r' % text)


@case
def option_quality_size(ctx):
    expect_option_error(ctx, 'quality', ['--size', '1e3x'], '--size', "'1e3x'")


@case
def help_prints_only(ctx):
    for program in ('sample', 'optimize', 'quality'):
        before = sorted(os.listdir(ctx.work))
        p = ctx.run(program, '--help', timeout=10)
        check(p.returncode == 0, '%s --help: exit status %d' % (program, p.returncode))
        check('Usage:' in p.stdout and p.stderr == '', '%s --help: not only the usage' % program)
        check(re.search(r'^Usage: bluenoise-%s \[OPTIONS\]' % program, p.stdout, re.M),
              '%s --help: no usage line' % program)
        check(sorted(os.listdir(ctx.work)) == before, '%s --help wrote files' % program)
        if program == 'sample':
            # The footer's table of files keeps its layout (CLI11 >= 2.5 would reflow it).
            check('\n  samples.vtp   the points' in p.stdout and
                  '\n                --samples NAME.csv' in p.stdout,
                  'sample --help: the footer lost its indentation')


# --- output ----------------------------------------------------------------------------
@case
def unwritable_output(ctx):
    volume = write(ctx.path('v.nii'), nifti_header((8, 8, 8)) + ramp(512))
    write(ctx.path('file'), b'x')
    p = ctx.run('sample', volume, '--no-pictures', '--output', ctx.path('file/out'))
    check(p.returncode == 1, 'exit status %d, expected 1' % p.returncode)
    check('file/out' in p.stderr and 'Not a directory' in p.stderr,
          "the message does not name the folder and the system's reason")


def write_existing_output(ctx):
    os.makedirs(ctx.out)
    for name in ('samples.vtp', 'spectrum.csv'):
        write(os.path.join(ctx.out, name), b'OLD ' + name.encode())
    return sorted(os.listdir(ctx.out))


def expect_existing_output(ctx, names):
    check(sorted(os.listdir(ctx.out)) == names, 'the output folder now holds %s'
          % sorted(os.listdir(ctx.out)))
    for name in ('samples.vtp', 'spectrum.csv'):
        check(open(os.path.join(ctx.out, name), 'rb').read() == b'OLD ' + name.encode(),
              '%s was overwritten' % name)


@case
def failed_run_keeps_output(ctx):
    volume = write(ctx.path('v.nii'), nifti_header((8, 8, 8)) + ramp(512))
    names = write_existing_output(ctx)
    # A hostile file: stopped before anything is written.
    short = write(ctx.path('short.nii'), nifti_header((64, 64, 64)) + ramp(10))
    check(ctx.sample(short).returncode == 1, 'the short file did not fail')
    expect_existing_output(ctx, names)
    # A failure at the very end (metrics.csv cannot replace a folder): the
    # files already written under temporary names are dropped.
    os.makedirs(os.path.join(ctx.out, 'metrics.csv', 'inside'))
    names = sorted(os.listdir(ctx.out))
    p = ctx.sample(volume, '--points', 50)
    check(p.returncode == 1 and 'metrics.csv' in p.stderr, 'the run did not fail on metrics.csv')
    expect_existing_output(ctx, names)


def sampled(ctx, volume, name, *extra):
    p = ctx.sample(volume, '--samples', name, *extra)
    check(p.returncode == 0, 'exit status %d' % p.returncode)
    return ctx.summary(p), os.path.join(ctx.out, name)


def read_csv(path):
    lines = open(path).read().splitlines()
    return lines[0].split(','), [[float(v) for v in line.split(',')] for line in lines[1:]]


@case
def csv_output(ctx):
    volume = write(ctx.path('v.nii'), nifti_header((16, 16, 16)) + ramp(4096))
    summary, path = sampled(ctx, volume, 'points.csv', '--points', 300)
    header, rows = read_csv(path)
    check(header[:3] == ['x', 'y', 'z'] and 'Density' in header, 'header %s' % header)
    check(len(rows) == int(summary['points']) and len(rows) > 250, '%d rows' % len(rows))
    check(all(len(r) == len(header) for r in rows), 'ragged rows')


@case
def ply_output(ctx):
    volume = write(ctx.path('v.nii'), nifti_header((16, 16, 16)) + ramp(4096))
    summary, path = sampled(ctx, volume, 'points.ply', '--points', 300)
    data = open(path, 'rb').read()
    end = data.index(b'end_header\n') + len(b'end_header\n')
    header = data[:end].decode().splitlines()
    check(header[0] == 'ply' and 'format binary_little_endian 1.0' in header, 'not a PLY')
    count = int([h for h in header if h.startswith('element vertex')][0].split()[2])
    properties = [h.split()[2] for h in header if h.startswith('property float')]
    check(count == int(summary['points']), 'element vertex %d' % count)
    check(properties[:3] == ['x', 'y', 'z'] and 'Density' in properties, str(properties))
    check(len(data) - end == 4 * len(properties) * count, 'body of %d bytes' % (len(data) - end))
    values = struct.unpack_from('<%df' % (len(properties) * count), data, end)
    xs = values[0::len(properties)]
    check(min(xs) >= 0 and max(xs) <= 15, 'x out of the volume')


def voxel_indices(rows, affine):
    """ijk of each point under the inverse of a 3x4 affine (rows), rounded, and
    the largest distance from a whole index."""
    a = [r[:3] for r in affine]
    t = [r[3] for r in affine]
    det = (a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
           - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
           + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]))
    inv = [[(a[(j + 1) % 3][(i + 1) % 3] * a[(j + 2) % 3][(i + 2) % 3]
             - a[(j + 1) % 3][(i + 2) % 3] * a[(j + 2) % 3][(i + 1) % 3]) / det
            for j in range(3)] for i in range(3)]
    worst, indices = 0.0, []
    for r in rows:
        p = [r[k] - t[k] for k in range(3)]
        ijk = [sum(inv[i][k] * p[k] for k in range(3)) for i in range(3)]
        worst = max(worst, max(abs(v - round(v)) for v in ijk))
        indices.append([round(v) for v in ijk])
    return indices, worst


def check_frame(ctx, volume, affine, frame, dims=(8, 6, 5), *extra):
    p = ctx.sample(volume, '--samples', 'p.csv', '--points', 60, *extra)
    check(p.returncode == 0, 'exit status %d' % p.returncode)
    check(ctx.summary(p)['frame'] == frame, 'frame %s, expected %s' % (ctx.summary(p)['frame'], frame))
    _, rows = read_csv(os.path.join(ctx.out, 'p.csv'))
    indices, worst = voxel_indices(rows, affine)
    check(worst < 1e-3, 'points are not at voxel centers of the file frame (off by %g)' % worst)
    check(all(0 <= ijk[k] < dims[k] for ijk in indices for k in range(3)),
          'points outside the volume in the file frame')
    check(len(set(map(tuple, indices))) == len(rows), 'two points on one voxel')


@case
def nifti_sform_frame(ctx):
    # Voxel (i, j, k) at x = 10 - 2 j, y = -20 + 3 i, z = 30 + 4 k millimetres.
    sform = [[0, -2, 0, 10], [3, 0, 0, -20], [0, 0, 4, 30]]
    volume = write(ctx.path('sform.nii'), nifti_header((8, 6, 5), pixdim=(3, 2, 4), sform=sform)
                   + ramp(240))
    check_frame(ctx, volume, sform, 'sform')
    # --voxel-space: origin 0, spacing pixdim.
    check_frame(ctx, volume, [[3, 0, 0, 0], [0, 2, 0, 0], [0, 0, 4, 0]], 'voxel', (8, 6, 5),
                '--voxel-space')


@case
def nifti_qform_frame(ctx):
    # A rotation of 90 degrees about z (quaternion b = c = 0, d = sin 45), offset (5, 6, 7).
    d = math.sqrt(0.5)
    volume = write(ctx.path('qform.nii'),
                   nifti_header((8, 6, 5), pixdim=(2, 3, 1.5), qform=(0, 0, d, 5, 6, 7))
                   + ramp(240))
    qform = [[0, -3, 0, 5], [2, 0, 0, 6], [0, 0, 1.5, 7]]
    check_frame(ctx, volume, qform, 'qform')


# --- small requests, streaming ------------------------------------------------------------
@case
def small_requests(ctx):
    volume = write(ctx.path('v.nii'), nifti_header((16, 16, 16)) + ramp(4096))
    summary, path = sampled(ctx, volume, 'five.csv', '--points', 5)
    check(int(summary['points']) == 5, 'points=%s for --points 5' % summary['points'])
    one = write(ctx.path('one.nii'), nifti_header((1, 1, 1)) + b'\x05')
    summary, path = sampled(ctx, one, 'one.csv')
    check(int(summary['points']) == 1, 'points=%s for a one-voxel volume' % summary['points'])


@case
def degenerate_volumes(ctx):
    # Constant and 2D volumes are sampled to the budget; an all-NaN one is a clear error.
    constant = write(ctx.path('constant.nii'), nifti_header((8, 8, 8)) + bytes([7] * 512))
    summary, _ = sampled(ctx, constant, 'constant.csv', '--points', 100)
    check(int(summary['points']) == 100, 'points=%s for a constant volume' % summary['points'])
    flat = write(ctx.path('flat.nii'), nifti_header((16, 16)) + bytes(range(256)))
    summary, _ = sampled(ctx, flat, 'flat.csv', '--points', 100)
    check(int(summary['points']) == 100, 'points=%s for a 2D volume' % summary['points'])
    nan = write(ctx.path('nan.nii'), nifti_header((8, 8, 8), datatype=16, bitpix=32)
                + struct.pack('<512f', *([float('nan')] * 512)))
    p = ctx.sample(nan)
    check(p.returncode == 1 and 'nan.nii' in p.stderr and 'no samples' in p.stderr,
          'an all-NaN volume does not fail clearly')


@case
def budget_out_of_reach(ctx):
    # 7 of 8 voxels can be drawn (one is at the bottom of the range): the
    # module's warning names the maximum.
    volume = write(ctx.path('v.nii'), nifti_header((2, 2, 2)) + bytes([0, 1, 2, 3, 4, 5, 6, 7]))
    p = ctx.sample(volume, '--points', 1000)
    check(p.returncode == 0, 'exit status %d' % p.returncode)
    check('warning' in p.stderr and 'at most 7' in p.stderr,
          'the budget warning does not reach the user')


@case
def streamed_equals_whole(ctx):
    # The same 24^3 ramp as a raw MetaImage, a raw NRRD and a VTI with raw
    # appended data (streamed in z-slabs) and as a NIfTI (read whole, voxel
    # space): the same points.
    dims = (24, 24, 24)
    data = ramp(24 * 24 * 24)
    write(ctx.path('v.raw'), data)
    p = ctx.sample(write(ctx.path('v.nii'), nifti_header(dims) + data), '--samples', 'whole.csv',
                   '--points', 800, '--voxel-space')
    check(p.returncode == 0 and 'streamed in' not in p.stdout, 'the NIfTI run failed')
    whole = read_csv(os.path.join(ctx.out, 'whole.csv'))[1]
    check(len(whole) > 700, '%d points' % len(whole))
    key = lambda rows: sorted(tuple(r[:3]) for r in rows)
    nrrd = b'NRRD0004\ntype: uint8\ndimension: 3\nsizes: 24 24 24\nencoding: raw\n\n' + data
    for volume in (metaimage(ctx.path('v.mhd'), dims, 'v.raw'),
                   write(ctx.path('v.nrrd'), nrrd),
                   vti_raw_appended(ctx.path('v.vti'), dims, data)):
        p = ctx.sample(volume, '--samples', 'streamed.csv', '--points', 800, '--slab-size', 0.002)
        check(p.returncode == 0 and 'streamed in ' in p.stdout, '%s was not streamed' % volume)
        slabs = int(p.stdout.split('streamed in ')[1].split()[0])
        check(slabs > 4, '%d slabs' % slabs)
        streamed = read_csv(os.path.join(ctx.out, 'streamed.csv'))[1]
        check(key(streamed) == key(whole), 'the points streamed from %s differ' % volume)


@case
def slabs_hold_a_part_per_thread(ctx):
    # 256 layers of 256^2 voxels: four z-parts (64 layers and 2^22 voxels
    # each). However small --slab-size, the threads get a slab of one part
    # each to sample side by side: 4 slabs on one thread, 2 on two; the
    # points are those of the volume read whole.
    dims = (256, 256, 256)
    write(ctx.path('v.raw'), bytes((z % 7) * 9 + 3 for z in range(256)
                                   for _ in range(256 * 256)))
    volume = metaimage(ctx.path('v.mhd'), dims, 'v.raw')
    points = {}
    for threads, slabs, size in ((1, 4, 0.002), (2, 2, 0.002), (2, 1, 1.0e6)):
        name = 'threads%d-slabs%d.csv' % (threads, slabs)
        p = ctx.sample(volume, '--samples', name, '--points', 20000, '--slab-size', size,
                       environment={'VTK_SMP_MAX_THREADS': str(threads)}, timeout=120)
        check(p.returncode == 0 and 'streamed in ' in p.stdout, '%s was not streamed' % volume)
        got = int(p.stdout.split('streamed in ')[1].split()[0])
        check(got == slabs, '%d slabs on %d threads, expected %d' % (got, threads, slabs))
        points[name] = sorted(tuple(r[:3]) for r in read_csv(os.path.join(ctx.out, name))[1])
    counts = [len(v) for v in points.values()]
    check(min(counts) > 19000 and all(v == points[name] for v in points.values()),
          'the slabs change the points (%s)' % counts)


@case
def metaimage_byte_order(ctx):
    # The same 16-bit ramp stored little-endian and big-endian, streamed in
    # z-slabs: the same points.
    dims = (20, 20, 20)
    values = [(37 * i) % 60000 for i in range(20 * 20 * 20)]
    rows = []
    for name, order in (('little', '<'), ('big', '>')):
        write(ctx.path(name + '.raw'), struct.pack(order + '%dH' % len(values), *values))
        volume = metaimage(ctx.path(name + '.mhd'), dims, name + '.raw', element='MET_USHORT',
                           big_endian=order == '>')
        p = ctx.sample(volume, '--samples', name + '.csv', '--points', 600, '--slab-size', 0.002)
        check(p.returncode == 0 and 'streamed in ' in p.stdout, '%s was not streamed' % volume)
        rows.append(sorted(tuple(r[:3]) for r in read_csv(os.path.join(ctx.out, name + '.csv'))[1]))
    check(len(rows[0]) > 500 and rows[0] == rows[1],
          'the big-endian volume gives other points (%d and %d)' % (len(rows[0]), len(rows[1])))


# --- methods and parameter sets: the filter's choices and defaults -----------------
SAMPLER_HEADER = os.path.join(os.path.dirname(os.path.dirname(os.path.dirname(
    os.path.abspath(__file__)))), 'Filters', 'Sampling', 'vtkErrorDiffusionSampler.h')
METHODS = ['relaxed-error-diffusion', 'error-diffusion', 'white-noise', 'poisson-disk',
           'sample-elimination']


def filter_defaults():
    """vtkErrorDiffusionSampler's C++ defaults of Method and ParameterSet, read from its
    header (`int Method = METHOD_RELAXED_ERROR_DIFFUSION;`), as the program's names:
    relaxed-error-diffusion, optimized."""
    found = {}
    for line in open(SAMPLER_HEADER):
        words = line.replace(';', ' ').split()
        if len(words) == 4 and words[0] == 'int' and words[2] == '=' and \
                words[1] in ('Method', 'ParameterSet'):
            prefix = 'METHOD_' if words[1] == 'Method' else 'PARAMETERS_'
            check(words[3].startswith(prefix), 'unexpected default %s' % line.strip())
            found[words[1]] = words[3][len(prefix):].lower().replace('_', '-')
    check(len(found) == 2, 'no Method or ParameterSet default in %s' % SAMPLER_HEADER)
    return found['Method'], found['ParameterSet']


def metrics(ctx):
    rows = open(os.path.join(ctx.out, 'metrics.csv')).read().splitlines()
    return dict(r.split(',', 1) for r in rows[1:])


def sampled_rows(ctx, volume, name, *extra):
    summary, path = sampled(ctx, volume, name, '--points', 300, *extra)
    return sorted(tuple(r[:3]) for r in read_csv(path)[1]), metrics(ctx)


@case
def default_method_is_the_filters(ctx):
    # The main job's defaults are the filter's (C++, and so pvpython and the
    # panel, whose XML defaults TestPluginProperties holds to the class's):
    # what metrics.csv names, and what the run really did (the same points as
    # with the filter's defaults named explicitly, not those of another set).
    method, parameters = filter_defaults()
    check(method in METHODS, 'the filter\'s default %s is not a --method choice' % method)
    volume = write(ctx.path('v.nii'), nifti_header((16, 16, 16)) + ramp(4096))
    default, named = sampled_rows(ctx, volume, 'default.csv')
    check(named.get('Method') == method and named.get('Parameters') == parameters,
          'metrics.csv names %s / %s, the filter\'s defaults are %s / %s' % (
              named.get('Method'), named.get('Parameters'), method, parameters))
    explicit, _ = sampled_rows(ctx, volume, 'explicit.csv', '--method', method,
                               '--parameters', parameters)
    check(len(default) > 250 and default == explicit,
          'the default run differs from --method %s --parameters %s' % (method, parameters))
    for other in ('paper', 'fixed'):
        if other != parameters:
            rows, named = sampled_rows(ctx, volume, other + '.csv', '--parameters', other)
            check(named.get('Parameters') == other and rows != default,
                  '--parameters %s gives the points of the default %s' % (other, parameters))
    p = ctx.run('sample', '--help')
    # CLI11 2.5+ wraps the descriptions: compare with the white space folded.
    text = ' '.join(p.stdout.split())
    check('(default %s)' % method in text and '(default %s)' % parameters in text,
          '--help does not name the defaults')


@case
def method_choices(ctx):
    # Every method of the filter by its name: a run, metrics.csv names it, the
    # count near the budget, and the peers' points are not the error
    # diffusion's (the relaxation may leave a sparse ramp as it is).
    volume = write(ctx.path('v.nii'), nifti_header((16, 16, 16)) + ramp(4096))
    seen = {}
    for method in METHODS:
        p = ctx.sample(volume, '--samples', method + '.csv', '--points', 300, '--method', method)
        check(p.returncode == 0, '--method %s: exit status %d' % (method, p.returncode))
        check(metrics(ctx).get('Method') == method, 'metrics.csv does not name %s' % method)
        check(('(--method %s ' % method) in p.stdout, 'stdout does not name %s' % method)
        points = int(ctx.summary(p)['points'])
        check(abs(points - 300) <= 30, '--method %s: %d points for 300' % (method, points))
        rows = sorted(tuple(r[:3]) for r in read_csv(os.path.join(ctx.out, method + '.csv'))[1])
        seen[method] = rows
    for method in ('white-noise', 'poisson-disk', 'sample-elimination'):
        check(seen[method] != seen['error-diffusion'],
              '--method %s gives the points of the error diffusion' % method)


@case
def option_method_unknown(ctx):
    expect_option_error(ctx, 'sample', ['--method', 'poisson'], '--method', "'poisson'",
                        'relaxed-error-diffusion', 'sample-elimination')
    expect_option_error(ctx, 'sample', ['--method', ''], '--method')


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument('--sample')
    parser.add_argument('--optimize')
    parser.add_argument('--quality')
    parser.add_argument('--work', default='program-inputs')
    parser.add_argument('--case')
    parser.add_argument('--list', action='store_true')
    args = parser.parse_args()
    if args.list:
        print('\n'.join(CASES))
        return 0
    ctx = Context(args)
    try:
        CASES[args.case](ctx)
    except Failure as failure:
        print('FAILED: %s: %s' % (args.case, failure))
        return 1
    print('passed: %s' % args.case)
    return 0


if __name__ == '__main__':
    sys.exit(main())
