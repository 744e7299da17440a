# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The sampler's whole pvpython UpdatePipeline against the tight loop.

    pvpython pvpython_update_pipeline.py --plugin BlueNoiseSampling.so \
        --tight-scan BlueNoiseTightScan.so [--sizes 256,512] [--repeats 5]

For each constant cube (edge 256 or 512, g = 8/255 and 127/255, uint8 and
float) and each method (the default, and the paper's error diffusion with its
Table 1), an Error Diffusion Sampler proxy with its defaults but for the
identity mapping and a budget of g * voxels (what BM_Filter does):
- first: its first UpdatePipeline, as a first Apply (a fresh output; the
  built-in tables' charges are known, nothing is calibrated);
- again: --repeats re-executions after a change of Seed, as a re-Apply (the
  first two are not counted: ParaView's post filter holds the last output
  while the filter runs again, so from the third on an execution writes into
  the memory of the output before the last).
Each timed UpdatePipeline is followed by the tight single-threaded loop of the
same scan (BlueNoiseTightScan.h: fastest of 3) under the same load, in this
process (the library BlueNoiseTightScan, loaded with ctypes) on the array the
sampler reads: x = loop seconds / UpdatePipeline seconds of each pair;
re-executions print the median and the lowest ratio; MiB = how much the
process's resident memory grew during the UpdatePipeline (a first execution
faults its output in; a re-execution writes into the memory of an earlier
output); fault s = the time to fault in that much fresh memory in this
process right after the first execution (the machine's share of it). No thresholds: figures for Documentation/Results.md
(scripts/results.py).
"""
import argparse
import ctypes
import os
import statistics
import sys
import time

import numpy as np
from paraview import servermanager
from paraview.simple import LoadPlugin, PVTrivialProducer
from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkImageData


def cube(n, g255, floats):
    """The image, and its values as a NumPy view of the array's memory."""
    image = vtkImageData()
    image.SetDimensions(n, n, n)
    values = np.full(n ** 3, g255 / 255.0 if floats else g255,
                     np.float32 if floats else np.uint8)
    array = numpy_to_vtk(values, deep=1)
    array.SetName('values')
    image.GetPointData().SetScalars(array)
    return image, vtk_to_numpy(array)


sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', 'Python'))
from bluenoise_testing import resident_bytes  # noqa: E402 (after the path)


def fault_seconds(mib):
    """Seconds to fault in `mib` MiB of fresh memory in this process (a byte
    written per page), what a first execution pays for an output that size."""
    if mib <= 0:
        return 0.0
    start = time.perf_counter()
    memory = np.empty(int(mib * 2.0 ** 20), np.uint8)
    memory[::4096] = 1
    seconds = time.perf_counter() - start
    del memory
    return seconds


def timed_update(sampler):
    """Seconds of one UpdatePipeline, and the MiB the resident memory grew by."""
    before, start = resident_bytes(), time.perf_counter()
    sampler.UpdatePipeline()
    return time.perf_counter() - start, (resident_bytes() - before) / 2.0 ** 20


class TightScan:
    """The tight loop of the library, on one cube's values, into a binary
    volume allocated once per edge (not per case)."""

    def __init__(self, path):
        self.library = ctypes.CDLL(path)
        self.library.bluenoise_tight_scan_seconds.restype = ctypes.c_double
        self.library.bluenoise_tight_scan_seconds.argtypes = [
            ctypes.c_void_p, ctypes.c_int, ctypes.c_int, ctypes.c_double, ctypes.c_void_p,
            ctypes.POINTER(ctypes.c_longlong)]
        self.volumes = {}

    def seconds(self, values, n):
        """Fastest of 3; densities value / 255 for 8-bit values, the value for floats."""
        b = self.volumes.setdefault(n, np.zeros(n ** 3, np.uint8))
        floats = values.dtype == np.float32
        points = ctypes.c_longlong(0)
        return self.library.bluenoise_tight_scan_seconds(
            values.ctypes.data, n, int(floats), 1.0 if floats else 1.0 / 255.0, b.ctypes.data,
            ctypes.byref(points))


METHODS = (('default', 'Relaxed Error Diffusion', 'Optimized'),
           ("paper's", 'Error Diffusion', 'Paper'))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--plugin', required=True)
    parser.add_argument('--tight-scan', required=True,
                        help='the library BlueNoiseTightScan (in the build\'s library folder)')
    parser.add_argument('--sizes', default='256,512')
    parser.add_argument('--repeats', type=int, default=5)
    args = parser.parse_args()
    LoadPlugin(args.plugin, remote=False, ns=globals())
    tight = TightScan(args.tight_scan)
    print('| edge | g | input | method | first s | first x | first MiB | fault s '
          '| again s (median) | again x: median (lowest) | again MiB (median) |')
    print('| ---: | ---: | --- | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: |')
    for n in [int(s) for s in args.sizes.split(',')]:
        for g255 in (8, 127):
            for floats in (0, 1):
                for label, method, table in METHODS:
                    producer = PVTrivialProducer()
                    image, values = cube(n, g255, floats)
                    producer.GetClientSideObject().SetOutput(image)
                    sampler = ErrorDiffusionSampler(Input=producer)  # noqa: F821 (from the plugin)
                    sampler.DensityMapping = 'Identity'
                    sampler.Method = method
                    sampler.ParameterSet = table
                    sampler.NumberOfPoints = int(g255 / 255.0 * n ** 3)
                    first, first_mib = timed_update(sampler)
                    fault = fault_seconds(first_mib)
                    first_plain = tight.seconds(values, n)
                    sampler.Seed = 100
                    sampler.UpdatePipeline()
                    times, plains, again_mib = [], [], []
                    for k in range(args.repeats):
                        sampler.Seed = k  # a change of property: the next update executes
                        seconds, grown = timed_update(sampler)
                        times.append(seconds)
                        again_mib.append(grown)
                        plains.append(tight.seconds(values, n))
                    ratios = [p / t for p, t in zip(plains, times)]
                    print('| %d | %d/255 | %s | %s | %.3f | %.2f | %.0f | %.3f | %.3f | %.2f (%.2f) | %.0f |' % (
                        n, g255, 'float' if floats else 'uint8', label, first, first_plain / first,
                        first_mib, fault, statistics.median(times), statistics.median(ratios),
                        min(ratios), statistics.median(again_mib)), flush=True)
                    servermanager.ProxyManager().UnRegisterProxies()
                    del sampler, producer, image, values


if __name__ == '__main__':
    main()
