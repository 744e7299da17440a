#!/usr/bin/python3
# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""Regenerates Documentation/Results.md from the project's benchmarks.

    /usr/bin/python3 scripts/results.py [BUILD_DIR] [--quick] [--only SECTIONS]
                                        [--quality] [--test-log FILE]
                                        [--fuzz-log TARGET=FILE ...]

BUILD_DIR (default _build/paraview, the first stage of scripts/test.sh) must
hold the benchmark programs (Google Benchmark, -DBLUENOISE_BUILD_BENCHMARKS=ON).
Each section of the page is one source, run here, and says when and on what
machine it was made and the exact command that made it:

  sampler    bin/BenchmarkErrorDiffusionSampler: the sampler against the tight
             single-threaded loop of the paper's scan, timed in the same run
  pvpython   Testing/Benchmarks/pvpython_update_pipeline.py under pvpython:
             the plugin's whole UpdatePipeline against the same loop
  peers      bin/BenchmarkPeerKernels: Poisson disk and sample elimination
             against the error-diffusion kernel
  spectrum   bin/BenchmarkSpectrum: the blue-noise spectrum's stages, 1 thread
             and every core, and FFTW's 3D plan
  streaming  scripts/bench-streaming.sh EDGE: peak memory, streamed and whole
  mpi        Testing/Benchmarks/mpi_scaling.py under mpiexec + pvbatch
  quality    Testing/QualityReport.md (scripts/quality-report.sh): L(g) by
             method and density, read from the report; --quality remakes the
             report first (about 20 minutes on 2 cores)
  stages     the stage times of a saved log of `bash scripts/test.sh`
             (--test-log FILE); without a log the section is kept as it was
  fuzz       long libFuzzer runs by hand (--fuzz-log TARGET=FILE[@COMMIT], each the
             output of a run with -print_final_stats=1; several for one target:
             runs continued in one WORK folder, added up): executions, speed and
             findings; targets not given keep their row

The full run measures every case of the programs, 3 repetitions each (the
512^3 cases take most of its time); --quick runs the smallest cases once (a
minute or two on 2 cores), enough to check the script and the programs, not
figures to quote. A section not selected by --only, or whose input is
missing (no pvpython, no mpiexec, no --test-log), is kept from the existing
page. The page is written only when every selected section ran.
"""
import argparse
import datetime
import glob
import json
import os
import re
import shlex
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SECTIONS = ['sampler', 'parts', 'pvpython', 'peers', 'spectrum', 'streaming', 'mpi', 'quality', 'stages', 'fuzz']
TITLES = {
    'sampler': 'Sampler speed (BenchmarkErrorDiffusionSampler)',
    'parts': 'Threads: z-parts projected to N cores (BM_PartsProjection)',
    'pvpython': 'The plugin through pvpython (UpdatePipeline)',
    'peers': 'The slower peers (BenchmarkPeerKernels)',
    'spectrum': 'Spectrum (BenchmarkSpectrum)',
    'streaming': 'Streaming (scripts/bench-streaming.sh)',
    'mpi': 'Distributed (mpi_scaling.py)',
    'quality': 'Blue noise (Testing/QualityReport.md)',
    'stages': 'Test suite stage times (scripts/test.sh)',
    'fuzz': 'Long fuzzer runs (Testing/Fuzz)',
}
MARK = '<!-- section: %s -->'
# Open MPI refuses root and more processes than cores unless told (as the tests do).
MPI_ENV = {'OMPI_ALLOW_RUN_AS_ROOT': '1', 'OMPI_ALLOW_RUN_AS_ROOT_CONFIRM': '1',
           'OMPI_MCA_rmaps_base_oversubscribe': '1'}


class Skip(Exception):
    """A section whose input is not there: the page keeps its last version."""


# --- the machine, the build, the commands -----------------------------------

def shown(path):
    """A path as the page shows it: relative to the repository when inside it."""
    path = os.path.abspath(path)
    rel = os.path.relpath(path, ROOT)
    return path if rel.startswith('..') else rel


def command_line(argv):
    return ' '.join(shlex.quote(a) for a in argv)


def machine(load=True):
    cpu = 'unknown CPU'
    with open('/proc/cpuinfo') as f:
        for line in f:
            if line.startswith('model name'):
                cpu = line.split(':', 1)[1].strip()
                break
    mem = 0
    with open('/proc/meminfo') as f:
        for line in f:
            if line.startswith('MemTotal:'):
                mem = int(line.split()[1]) / 1024.0 ** 2
                break
    what = '%d cores, %.1f GiB, %s' % (os.cpu_count() or 1, mem, cpu)
    if not load:
        return what
    nice = os.nice(0)
    return '%s; load average %.2f at the start%s' % (
        what, os.getloadavg()[0], ', niceness %d' % nice if nice else '')


def now():
    return datetime.datetime.now(datetime.timezone.utc).strftime('%Y-%m-%d %H:%M UTC')


def cache_value(build, key):
    try:
        with open(os.path.join(build, 'CMakeCache.txt')) as f:
            for line in f:
                if line.startswith(key + ':'):
                    return line.split('=', 1)[1].strip()
    except OSError:
        pass
    return None


def build_description(build, program=None):
    """The build a section's programs come from: type, SDK, source commit."""
    parts = ['build `%s`' % shown(build)]
    kind = cache_value(build, 'CMAKE_BUILD_TYPE')
    if kind:
        parts.append(kind)
    sdk = cache_value(build, 'ParaView_DIR') or cache_value(build, 'VTK_DIR')
    if sdk:
        parts.append('against `%s`' % sdk)
    source = cache_value(build, 'BlueNoiseSampling_SOURCE_DIR') or cache_value(build, 'CMAKE_HOME_DIRECTORY')
    if source:
        try:
            commit = subprocess.run(['git', '-C', source, 'rev-parse', '--short', 'HEAD'],
                                    capture_output=True, text=True, check=True).stdout.strip()
            # This page itself, written a section at a time, is no change to the source.
            changed = subprocess.run(['git', '-C', source, 'status', '--porcelain', '--', '.',
                                      ':!Documentation/Results.md'],
                                     capture_output=True, text=True, check=True).stdout.strip()
            parts.append('source at commit `%s%s`' % (commit, '-dirty' if changed else ''))
        except (OSError, subprocess.CalledProcessError):
            pass
    if program and os.path.exists(program):
        stamp = datetime.datetime.fromtimestamp(os.path.getmtime(program), datetime.timezone.utc)
        parts.append('`%s` built %s' % (os.path.basename(program), stamp.strftime('%Y-%m-%d %H:%M UTC')))
    return ', '.join(parts)


def provenance(date, where, commands, build=None, mode=None):
    lines = ['- Made: %s, on %s.' % (date, where)]
    if build:
        lines.append('- Programs: %s.' % build)
    if mode:
        lines.append('- Mode: %s.' % mode)
    lines.append('- Command%s:' % ('s' if len(commands) > 1 else ''))
    lines.append('')
    lines.extend('      ' + c for c in commands)
    lines.append('')
    return lines


def run(argv, env=None, cwd=ROOT):
    print('results: ' + command_line(argv), file=sys.stderr, flush=True)
    full_env = dict(os.environ)
    full_env.update(env or {})
    done = subprocess.run(argv, cwd=cwd, env=full_env, capture_output=True, text=True)
    if done.returncode != 0:
        sys.stderr.write(done.stdout[-4000:] + done.stderr[-4000:])
        raise SystemExit('results: failed (exit status %d): %s' % (done.returncode, command_line(argv)))
    return done.stdout


def program(build, name):
    path = os.path.join(build, 'bin', name)
    if not os.access(path, os.X_OK):
        raise Skip('`%s` not found (a build with -DBLUENOISE_BUILD_BENCHMARKS=ON and Google Benchmark)'
                   % shown(path))
    return path


# --- Google Benchmark programs ------------------------------------------------

def benchmark(build, name, filt, repetitions, quick, scratch):
    """Runs a benchmark program; returns (display command, {run name: [runs]})."""
    exe = program(build, name)
    out = os.path.join(scratch, name + '.json')
    args = ['--benchmark_filter=' + filt, '--benchmark_repetitions=%d' % repetitions]
    if quick:
        args.append('--benchmark_min_time=0')
    run([exe] + args + ['--benchmark_out=' + out, '--benchmark_out_format=json'])
    with open(out) as f:
        data = json.load(f)
    runs = {}
    for b in data['benchmarks']:
        if b.get('run_type', 'iteration') != 'iteration' or b.get('error_occurred') or b.get('skipped'):
            continue
        key = b.get('run_name', b['name'])
        key = key[:-len('/real_time')] if key.endswith('/real_time') else key
        runs.setdefault(key, []).append(b)
    if not runs:
        raise SystemExit('results: %s ran no case for --benchmark_filter=%s' % (name, filt))
    shown_cmd = command_line([shown(exe)] + args + ['--benchmark_out=%s.json' % name,
                                                    '--benchmark_out_format=json'])
    return shown_cmd, runs


def named_args(key):
    """'BM_Filter/L:256/g255:8/...' -> ('BM_Filter', {'L': 256, 'g255': 8, ...})."""
    parts = key.split('/')
    args = {}
    for i, p in enumerate(parts[1:]):
        name, _, value = p.rpartition(':')
        args[name or str(i)] = int(value) if re.fullmatch(r'-?\d+', value) else value
    return parts[0], args


def seconds(b):
    scale = {'ns': 1e-9, 'us': 1e-6, 'ms': 1e-3, 's': 1.0}[b.get('time_unit', 'ns')]
    return b['real_time'] * scale


def spread(values, digits=2):
    """median (lowest) of the repetitions, or the single value."""
    if not values:
        return ''
    if len(values) == 1:
        return '%.*f' % (digits, values[0])
    return '%.*f (%.*f)' % (digits, statistics.median(values), digits, min(values))


def ms(values):
    return '%.0f' % (1e3 * statistics.median(values)) if values else ''


def table(header, rows, align=None):
    align = align or ['---'] + ['---:'] * (len(header) - 1)
    lines = ['| ' + ' | '.join(header) + ' |', '| ' + ' | '.join(align) + ' |']
    lines += ['| ' + ' | '.join(str(c) for c in r) + ' |' for r in rows]
    return lines + ['']


def g_label(g255):
    return '%d/255' % g255


# --- sections ----------------------------------------------------------------

def section_sampler(opts, scratch):
    if opts.quick:
        filt = ('^BM_Kernel/L:256/|^BM_Relaxation/L:256/g255:8/rule:0$|'
                '^BM_Filter/L:256/g255:(8|127)/float:[01]/busy:0/thread:1/')
        reps = 1
    else:
        filt = '^BM_(Kernel|Relaxation|Filter|Steps)/'
        reps = 3
    date, where = now(), machine()
    cmd, runs = benchmark(opts.build, 'BenchmarkErrorDiffusionSampler', filt, reps, opts.quick, scratch)
    kernel, relax, filt_runs, steps = [], [], {}, {}
    for key, rs in runs.items():
        fam, a = named_args(key)
        if fam == 'BM_Kernel':
            kernel.append((a['L'], a['g255'], rs))
        elif fam == 'BM_Relaxation':
            relax.append((a['rule'], a['L'], a['g255'], rs))
        elif fam == 'BM_Filter':
            filt_runs[(a['L'], a['g255'], a['float'], a['busy'], a['thread'], a['method'])] = rs
        elif fam == 'BM_Steps':
            steps[a['method']] = rs
    out = provenance(date, where, [cmd], build_description(
        opts.build, os.path.join(opts.build, 'bin', 'BenchmarkErrorDiffusionSampler')),
        'quick (the 256^3 cases, one repetition, one iteration each)' if opts.quick
        else '%d repetitions of every case' % reps)
    out += [
        'x_tight = the time of the tight single-threaded loop of the paper\'s scan (`TightScan`',
        'in `Testing/Benchmarks/BlueNoiseTightScan.h` says what it does and does not do) on the same',
        'cube (fastest of 3, timed right before the case and, for the filter, right after it',
        'too: the faster of the two) / the time of the case; higher is faster. Each cell:',
        'the median of the repetitions, the lowest in brackets (one value for one',
        'repetition). Constant cubes, a budget of g x voxels, the identity mapping, `Jitter`',
        'off; the filter re-executes as after a change of property. Default: relaxed error',
        'diffusion with the Optimized parameters; paper\'s: error diffusion with Table 1.',
        '']
    rows = []
    for L, g, rs in sorted(kernel):
        rows.append(['%d^3' % L, g_label(g), ms([seconds(b) for b in rs]),
                     spread([b['x_tight'] for b in rs if 'x_tight' in b])])
    if rows:
        out += ['The error-diffusion kernel alone (its default parameters, the paper\'s Table 1; no',
                'pipeline; below g = 0.05 and above 0.95 its scan branches on whether a voxel',
                'fires, in between it does not, see `ScanRun` in `vtkErrorDiffusionScan.cxx`):',
                '']
        out += table(['cube', 'g', 'ms (median)', 'x_tight'], rows)
    rows = []
    for L, g, fl, busy, thread in sorted({k[:5] for k in filt_runs}):
        if busy:
            continue
        cells = ['float' if fl else 'uint8', '%d^3' % L, g_label(g)]
        for method in (2, 5, 0):
            rs = filt_runs.get((L, g, fl, busy, thread, method), [])
            cells += [ms([seconds(b) for b in rs]), spread([b['x_tight'] for b in rs])]
        rows.append(cells)
    if rows:
        out += ['The filter (`vtkErrorDiffusionSampler`, worker thread allowed):', '']
        out += table(['input', 'cube', 'g', 'default: ms', 'default: x_tight', 'energy: ms',
                      'energy: x_tight', 'paper\'s: ms', 'paper\'s: x_tight'], rows,
                     ['---'] * 3 + ['---:'] * 6)
    rows = []
    for key in sorted(k for k in filt_runs if k[3]):
        L, g, fl, busy, thread, method = key
        rs = filt_runs[key]
        rows.append(['default' if method == 2 else 'paper\'s', '%d^3' % L, g_label(g),
                     'on' if thread else 'off', ms([seconds(b) for b in rs]),
                     spread([b['x_tight'] for b in rs])])
    if rows:
        out += ['With every core busy (another process spinning on each core), uint8:', '']
        out += table(['method', 'cube', 'g', 'worker thread', 'ms', 'x_tight'], rows,
                     ['---'] * 4 + ['---:'] * 2)
    rows = []
    for L, g, fl, busy, thread in sorted({k[:5] for k in filt_runs}):
        d = filt_runs.get((L, g, fl, busy, thread, 2))
        e = filt_runs.get((L, g, fl, busy, thread, 5))
        p = filt_runs.get((L, g, fl, busy, thread, 0))
        if busy or not d or not p:
            continue
        paper = statistics.median(seconds(b) for b in p)
        rows.append(['float' if fl else 'uint8', '%d^3' % L, g_label(g),
                     '%.2f' % (statistics.median(seconds(b) for b in d) / paper),
                     '%.2f' % (statistics.median(seconds(b) for b in e) / paper) if e else ''])
    if rows:
        out += ['The relaxed methods\' time / the paper\'s method\'s (medians; above 1/4 nothing',
                'is relaxed and they do the same work, so there the ratio is the spread of the',
                'machine):', '']
        out += table(['input', 'cube', 'g', 'default / paper\'s', 'energy / paper\'s'], rows,
                     ['---'] * 3 + ['---:'] * 2)
    rows = [[name, ms([seconds(b) for b in steps[m]]), spread([b['x_tight'] for b in steps[m]])]
            for m, name in ((2, 'default'), (0, 'paper\'s')) if m in steps]
    if rows:
        ratio = ''
        if len(rows) == 2:
            ratio = ' The default method\'s time / the paper\'s: %.2f (medians).' % (
                statistics.median(seconds(b) for b in steps[2]) /
                statistics.median(seconds(b) for b in steps[0]))
        out += ['A volume of density steps (`BM_Steps`): 256^3 uint8 of 8^3 blocks, each of a',
                'value drawn from 2 .. 64 (densities value / 255), the budget the sum of the',
                'densities; x_tight against the tight loop on the same volume.' + ratio, '']
        out += table(['method', 'ms (median)', 'x_tight'], rows, ['---', '---:', '---:'])
    rows = []
    for rule, L, g, rs in sorted(relax):
        rows.append(['energy' if rule else 'spacing (default)', '%d^3' % L, g_label(g),
                     ms([seconds(b) for b in rs]),
                     spread([1.0 / b['x_kernel'] for b in rs if b.get('x_kernel')]),
                     '%d' % statistics.median(b['moves'] for b in rs)])
    if rows:
        out += ['One relaxation pass alone (`BM_Relaxation`, on the kernel\'s samples of the cube;',
                'it runs on the calling thread while the worker thread scans; the energy relaxed method',
                'runs two energy passes, one after the other):', '']
        out += table(['rule', 'cube', 'g', 'ms (median)', 'relaxation / kernel time', 'moves'], rows,
                     ['---'] * 3 + ['---:'] * 3)
    return out


def section_parts(opts, scratch):
    filt = '^BM_PartsProjection/L:512/g255:8/' if opts.quick else '^BM_PartsProjection/'
    date, where = now(), machine()
    cmd, runs = benchmark(opts.build, 'BenchmarkErrorDiffusionSampler', filt, 1, opts.quick, scratch)
    out = provenance(date, where, [cmd], build_description(
        opts.build, os.path.join(opts.build, 'bin', 'BenchmarkErrorDiffusionSampler')),
        'one run of every case' if not opts.quick else 'quick (512^3 at 8/255 only)')
    out += [
        'The sampler cuts a volume into z-parts (*Part Layers*, *Part Voxels*) and samples',
        'them side by side, each thread taking the next part when its own is done. x_N =',
        'the time of the whole cube in one part on one thread / the wall time the parts',
        'would take on N threads: each part\'s own layers and its overlap timed alone (so',
        'the overlap\'s extra scan is counted, with its relaxation and points), on one thread',
        'and with the worker thread beside it (paired: two threads), and the filter\'s schedule',
        'replayed: the next part going to the first thread free, in epochs of half a second;',
        'threads the parts leave idle pair up with the lowest parts held, decided afresh every',
        'tenth of a second (the filter: at each chunk); the last part left paired. Paired = the',
        'parts\' time paired / alone. Two threads at most are used: the machine measuring need',
        'not have N cores. uint8 volumes: constant cubes of density g, a budget of g x voxels; and the',
        'graded ball of `scripts/bench-streaming.sh` (255 at its center, times 0.75 to 1 by',
        'layer, to 0 at its surface), densities value / 255 x g, whose middle parts hold',
        'most of the work. Part layers: *Part Layers* (default 64).',
        '']
    rows, streamed = [], []
    order = lambda kv: tuple(named_args(kv[0])[1].get(k, 0) for k in ('ball', 'L', 'g255', 'layers'))
    for key, rs in sorted(runs.items(), key=lambda kv: order(kv) + (-named_args(kv[0])[1]['method'],)):
        _, a = named_args(key)
        b = rs[0]
        case = ['default' if a['method'] == 2 else 'paper\'s',
                '%s %d^3' % ('graded ball' if a.get('ball') else 'cube', a['L']), g_label(a['g255']),
                '%d' % (a.get('layers') or 64)]
        rows.append(case + ['%d' % b['parts'], '%.2f' % b['overlap'], '%.1f' % b['one_part_s'],
                            '%.2f' % b['paired']] +
                    ['%.2f' % b['x_%d' % n] for n in (2, 4, 8, 16)])
        streamed.append(case + ['%d' % max(1, int(b['parts']) // min(int(b['parts']), n))
                                for n in (2, 4, 8, 16)] +
                        ['%.2f' % b['xs_%d' % n] for n in (2, 4, 8, 16)])
    out += table(['method', 'volume', 'g', 'part layers', 'parts', 'layers scanned / layers',
                  'one part, one thread: s', 'paired', 'x_2', 'x_4', 'x_8', 'x_16'], rows,
                 ['---'] * 3 + ['---:'] * 9)
    out += ['Streamed as `bluenoise-sample` streams a volume of several parts on N threads:',
            'in max(1, parts / N) z-slabs one after the other (slabs of a part per thread at',
            'least), the parts side by side within each slab only; xs_N = the same one-part time',
            '/ the replayed wall time of the slabs. Where the work sits in a few parts (the ball),',
            'a slab waits for its densest part, and a larger `--slab-size` (more parts a slab) or',
            'the volume read whole balances the threads better.', '']
    out += table(['method', 'volume', 'g', 'part layers', 'slabs, N = 2', 'N = 4', 'N = 8',
                  'N = 16', 'xs_2', 'xs_4', 'xs_8', 'xs_16'], streamed,
                 ['---'] * 3 + ['---:'] * 9)
    return out


def section_pvpython(opts, scratch):
    library = os.path.join(opts.build, 'lib', 'libBlueNoiseTightScan.so')
    if not os.path.exists(library):
        raise Skip('`%s` not found (a build with -DBLUENOISE_BUILD_BENCHMARKS=ON and Google Benchmark)'
                   % shown(library))
    plugins = sorted(glob.glob(os.path.join(opts.build, 'lib', 'paraview-*', 'plugins',
                                            'BlueNoiseSampling', 'BlueNoiseSampling.so')))
    pvpython = opts.pvpython or shutil.which('pvpython')
    if not plugins:
        raise Skip('no ParaView plugin in `%s`' % shown(opts.build))
    if not pvpython:
        raise Skip('no pvpython')
    sizes, repeats = ('256', 2) if opts.quick else ('256,512', 5)
    argv = [pvpython, os.path.join(ROOT, 'Testing/Benchmarks/pvpython_update_pipeline.py'),
            '--plugin', plugins[-1], '--tight-scan', library, '--sizes', sizes, '--repeats', str(repeats)]
    date, where = now(), machine()
    text = run(argv)
    shown_argv = [pvpython, 'Testing/Benchmarks/pvpython_update_pipeline.py', '--plugin',
                  shown(plugins[-1]), '--tight-scan', shown(library), '--sizes', sizes,
                  '--repeats', str(repeats)]
    out = provenance(date, where, [command_line(shown_argv)],
                     build_description(opts.build, plugins[-1]),
                     'quick (256^3 only, 2 re-executions a case)' if opts.quick else None)
    out += ['The proxy\'s defaults (`Jitter` on) but for the identity mapping and a budget of',
            'g x voxels, with the default method and with the paper\'s (Table 1). *first*: the',
            'first `UpdatePipeline` of a new proxy, as a first Apply (a fresh output; the',
            'built-in tables\' charges are known, nothing is calibrated); *again*: re-executions',
            'after a change of `Seed`, as a re-Apply (the first two not counted, see the script).',
            'Each timed `UpdatePipeline` is followed by the tight loop (fastest of 3) under the',
            'same load, in pvpython\'s process on the array the sampler reads (the library',
            '`BlueNoiseTightScan`, loaded with ctypes); x = loop / UpdatePipeline of each pair, for',
            '*again* the median and the lowest in brackets. MiB: how much the process\'s resident',
            'memory grew during the `UpdatePipeline` (a first execution faults its output in, a',
            're-execution writes into the memory of an earlier output); *fault s*: the time to',
            'fault in that much fresh memory in the same process right after (a byte written per',
            'page), the machine\'s share of a first execution.', '']
    out += [l for l in text.splitlines() if l.startswith('|')] + ['']
    return out


def section_peers(opts, scratch):
    filt, reps = ('/L:64/', 1) if opts.quick else ('.', 3)
    date, where = now(), machine()
    cmd, runs = benchmark(opts.build, 'BenchmarkPeerKernels', filt, reps, opts.quick, scratch)
    cases = {}
    for key, rs in runs.items():
        fam, a = named_args(key)
        kind = 'ed' if fam == 'BM_ErrorDiffusion' else 'pd' if 'PoissonDisk' in fam else 'se'
        cases.setdefault((a['L'], a['g255']), {})[kind] = rs
    rows = []
    for (L, g), c in sorted(cases.items()):
        cells = ['%d^3' % L, g_label(g), ms([seconds(b) for b in c.get('ed', [])])]
        for kind in ('pd', 'se'):
            rs = c.get(kind, [])
            cells += [ms([seconds(b) for b in rs]), spread([b['vs_ED'] for b in rs if 'vs_ED' in b], 0)]
        rows.append(cells)
    out = provenance(date, where, [cmd], build_description(
        opts.build, os.path.join(opts.build, 'bin', 'BenchmarkPeerKernels')),
        'quick (64^3, one repetition, one iteration each)' if opts.quick
        else '%d repetitions of every case' % reps)
    out += ['The kernels alone on constant cubes; vs_ED = the peer\'s time / the error-diffusion',
            'kernel\'s on the same cube in the same run (median, lowest in brackets).', '']
    out += table(['cube', 'g', 'error diffusion ms', 'Poisson disk ms', 'Poisson disk vs_ED',
                  'sample elimination ms', 'sample elimination vs_ED'], rows, ['---'] * 2 + ['---:'] * 5)
    return out


def section_spectrum(opts, scratch):
    filt, reps = ('/(64|128)/', 1) if opts.quick else ('.', 3)
    date, where = now(), machine()
    cmd, runs = benchmark(opts.build, 'BenchmarkSpectrum', filt, reps, opts.quick, scratch)
    times = {}
    for key, rs in runs.items():
        parts = key.split('/')
        times[(parts[0][3:], int(parts[1]), int(parts[2]))] = statistics.median(seconds(b) for b in rs)
    threads = sorted({k[2] for k in times})
    many = threads[-1]
    order = ['Fresh', 'Reused', 'Transform', 'Compute', 'Filter', 'FilterImage', 'FFTW3D']
    rows = []
    for stage in order:
        for n in sorted({k[1] for k in times if k[0] == stage}):
            one, more = times.get((stage, n, 1)), times.get((stage, n, many))
            rows.append([stage, '%d^3' % n, '%.1f' % (1e3 * one) if one else '',
                         '%.1f' % (1e3 * more) if more and many > 1 else '',
                         '%.2f' % (one / more) if one and more and many > 1 else ''])
    out = provenance(date, where, [cmd], build_description(
        opts.build, os.path.join(opts.build, 'bin', 'BenchmarkSpectrum')),
        'quick (64^3 and 128^3, one repetition, one iteration each)' if opts.quick
        else '%d repetitions of every case' % reps)
    out += ['The spectrum of one random mask at g = 0.05 on an L^3 grid (vtkSMPTools\' STDThread',
            'backend). Fresh: a new kernel each run; Reused: a kept kernel reset and run again;',
            'Transform: the FFT and power alone; Compute: the shell pass alone; Filter /',
            'FilterImage: `vtkBlueNoiseSpectrum` on the mask\'s points without / with the',
            'spectrum image; FFTW3D: FFTW\'s one-call 3D plan with as many FFTW threads.',
            'Medians of the repetitions, wall-clock milliseconds.', '']
    out += table(['stage', 'grid', '1 thread ms', '%d threads ms' % many, 'speed-up'], rows)
    rows = []
    for (stage, n, t), v in sorted(times.items()):
        if stage == 'FFTW3D' and ('Transform', n, t) in times:
            rows.append(['%d^3' % n, t, '%.2f' % (v / times[('Transform', n, t)])])
    if rows:
        out += ['FFTW\'s 3D plan / the kernel\'s slab and column Transform (same thread count;',
                'above 1: the kernel\'s transform is faster):', '']
        out += table(['grid', 'threads', 'FFTW3D / Transform'], rows)
    return out


def section_streaming(opts, scratch):
    exe = os.path.join(opts.build, 'bin', 'bluenoise-sample')
    if not os.access(exe, os.X_OK):
        raise Skip('`%s` not found' % shown(exe))
    if not os.access('/usr/bin/time', os.X_OK):
        raise Skip('no /usr/bin/time')
    edges = ['512'] if opts.quick else opts.streaming_edges.split(',')
    points = '1000000'
    date, where = now(), machine()
    rows, cmds = [], []
    for edge in edges:
        argv = ['bash', os.path.join(ROOT, 'scripts/bench-streaming.sh'), edge, points, opts.build]
        cmds.append(command_line(['bash', 'scripts/bench-streaming.sh', edge, points, shown(opts.build)]))
        text = run(argv)
        found = {}
        for name in ('whole', 'streamed'):
            m = re.search(r'^%s: peak RSS (\d+) MiB, wall ([\d.]+) s, sampling ([\d.]+) s' % name, text, re.M)
            if not m:
                raise SystemExit('results: unexpected output of bench-streaming.sh:\n' + text)
            found[name] = m.groups()
        slabs = re.findall(r'streamed in (\d+) z-slabs', text)
        n = int(edge)
        rows.append(['%d^3 (%s)' % (n, size_label(n ** 3)), '%s MiB, %s' % (found['streamed'][0], slabs[-1]),
                     '%s MiB' % found['whole'][0], '%.2f (%.1f s / %.1f s)' % (
                         float(found['streamed'][1]) / float(found['whole'][2]),
                         float(found['streamed'][1]), float(found['whole'][2]))])
    out = provenance(date, where, cmds, build_description(opts.build, exe),
                     'quick (512^3 only)' if opts.quick else None)
    out += ['A generated uint8 raw MetaImage of EDGE^3 voxels sampled into %s points by' % points,
            '`bluenoise-sample`: streamed in z-slabs of the default `--slab-size` (64 MiB), and',
            'read whole (one slab larger than the volume). Peak resident memory from',
            '`/usr/bin/time -v`; the sampling alone is the whole run\'s `seconds=` (the sampler',
            'on the volume in memory).', '']
    out += table(['volume', 'streamed: peak RSS, slabs', 'read whole: peak RSS',
                  'streamed wall time / sampling alone'], rows)
    return out


def size_label(nbytes):
    return '%d GiB' % (nbytes >> 30) if nbytes >= 1 << 30 else '%d MiB' % (nbytes >> 20)


def section_mpi(opts, scratch):
    mpiexec = shutil.which('mpiexec') or shutil.which('mpirun')
    pvbatch = opts.pvbatch or shutil.which('pvbatch')
    pythonpath = os.path.join(opts.build, 'lib', 'python3', 'dist-packages')
    if not mpiexec or not pvbatch:
        raise Skip('no mpiexec or no pvbatch')
    if not os.path.isdir(os.path.join(pythonpath, 'bluenoise')):
        raise Skip('no `bluenoise` Python package in `%s`' % shown(pythonpath))
    edge, counts = ('128', [1, 2]) if opts.quick else ('256', [1, 2, 3, 4])
    date, where = now(), machine()
    env = dict(MPI_ENV, PYTHONPATH=pythonpath)
    rows, cmds = [], []
    for n in counts:
        argv = [mpiexec, '-n', str(n), pvbatch, '--symmetric',
                os.path.join(ROOT, 'Testing/Benchmarks/mpi_scaling.py'), '--edge', edge]
        cmds.append('PYTHONPATH=%s %s' % (shown(pythonpath), command_line(
            [os.path.basename(mpiexec), '-n', str(n), pvbatch, '--symmetric',
             'Testing/Benchmarks/mpi_scaling.py', '--edge', edge])))
        rows += [l for l in run(argv, env).splitlines() if l.startswith('|')]
    out = provenance(date, where, cmds, build_description(opts.build),
                     'quick (128^3, 1 and 2 processes)' if opts.quick else None)
    out += ['A constant %s^3 volume, each process sampling its piece (default method, a' % edge,
            'budget of 2 % of the voxels), the spectrum by `vtkPBlueNoiseSpectrum` on the gathered',
            'points; seconds: the slowest process. (Open MPI run as root with `%s`.)' % ' '.join(
                '%s=%s' % kv for kv in sorted(MPI_ENV.items())), '']
    out += ['| processes | seconds | points | L(g) | mean anisotropy (dB) |',
            '| ---: | ---: | ---: | ---: | ---: |'] + rows + ['']
    return out


QUALITY_ORDER = ['Relaxed', 'RelaxedSubCube', 'Energy', 'EnergySubCube', 'Paper', 'ContinuousPoissonDisk', 'PoissonDisk', 'SampleElimination',
                 'WhiteNoise', 'Optimized', 'Fixed']
QUALITY_NAMES = {
    'Relaxed': 'default (relaxed, Optimized)',
    'RelaxedSubCube': 'default, the cube inside a varying volume',
    'Energy': 'energy relaxed (Optimized)', 'EnergySubCube': 'energy relaxed, the cube inside a varying volume',
    'Paper': 'paper\'s error diffusion (Table 1)',
    'ContinuousPoissonDisk': 'Poisson disk, continuous', 'PoissonDisk': 'Poisson disk on the voxels',
    'SampleElimination': 'sample elimination', 'WhiteNoise': 'white noise',
    'Optimized': 'error diffusion, Optimized', 'Fixed': 'error diffusion, Fixed'}


def section_quality(opts, scratch):
    report = os.path.join(ROOT, 'Testing', 'QualityReport.md')
    cmds = []
    if opts.quality:
        if not os.access(os.path.join(opts.build, 'bin', 'bluenoise-quality'), os.X_OK):
            raise SystemExit('results: no bluenoise-quality in %s' % opts.build)
        run(['bash', os.path.join(ROOT, 'scripts/quality-report.sh')],
            {'BLUENOISE_BUILD_DIR': os.path.abspath(opts.build)})
        cmds.append('BLUENOISE_BUILD_DIR=%s bash scripts/quality-report.sh' % shown(opts.build))
        where = machine()
    else:
        where = 'a machine the report does not record (fixed seeds)'
    if not os.path.exists(report):
        raise Skip('no Testing/QualityReport.md')
    with open(report) as f:
        text = f.read()
    head = re.search(r'Generated by `([^`]*)` on (\S+) \(`([^`]*)`\)', text)
    if not head:
        raise SystemExit('results: Testing/QualityReport.md has no "Generated by" line')
    if not cmds:
        cmds.append(head.group(1))
    cmds.append(head.group(3).strip() + '   (what the script runs)')
    setup = re.search(r'^(Whole .*)$', text, re.M)
    values = {}
    for m in re.finditer(r'^\| (\d+) \| (\w+) \| ([^|]+) \| ([\d.]+) ± ([\d.]+) \| ([^|]+) \| ([^|]+) \|$',
                         text, re.M):
        values[(int(m.group(1)), m.group(2))] = (float(m.group(4)), float(m.group(5)),
                                                 m.group(7).strip())
    levels = sorted({k[0] for k in values})
    methods = [m for m in QUALITY_ORDER if any((l, m) in values for l in levels)]
    out = provenance(head.group(2), where, cmds, None, None)
    out += ['The low-frequency energy L(g) of each method (lower is better), read from',
            '`Testing/QualityReport.md`, which holds every table (T(g), S(g), the anisotropy, the',
            'local density). The report\'s set-up:', '',
            '> ' + (setup.group(1) if setup else '(not found)'), '']
    rows = []
    for l in levels:
        best = min(values[(l, m)][0] for m in methods
                   if m not in ('WhiteNoise', 'RelaxedSubCube', 'EnergySubCube') and (l, m) in values)
        cells = ['%d/255' % l]
        for m in methods:
            v = values.get((l, m))
            cells.append(('**%.4f**' if v and v[0] == best else '%.4f') % v[0] if v else '')
        rows.append(cells)
    out += table(['g'] + [QUALITY_NAMES[m] for m in methods], rows)
    out += ['(bold: the lowest but white noise\'s and those in a varying volume.)',
            'The default\'s L(g) against each method, in % of that method\'s (negative: the',
            'default is lower); "=" where the two differ by less than the larger standard',
            'deviation:', '']
    rows = []
    for m in methods:
        if m == 'Relaxed':
            continue
        cells = [QUALITY_NAMES[m]]
        for l in levels:
            a, b = values.get((l, 'Relaxed')), values.get((l, m))
            if not a or not b:
                cells.append('')
                continue
            pct = 100.0 * (a[0] - b[0]) / b[0]
            cells.append(("= (%+.1f)" if abs(a[0] - b[0]) <= max(a[1], b[1]) else "%+.1f") % pct)
        rows.append(cells)
    out += table(['default against'] + ['%d/255' % l for l in levels], rows)
    bullets = [l for l in text.splitlines() if l.startswith('- mean ')]
    if bullets:
        out += ['The report\'s own checks, verbatim:', ''] + bullets + ['']
    return out


def section_stages(opts, scratch):
    if not opts.test_log:
        raise Skip('no --test-log')
    with open(opts.test_log, errors='replace') as f:
        text = f.read()
    block = text.split('=== stage times', 1)
    if len(block) < 2:
        raise SystemExit('results: no "=== stage times" in %s' % opts.test_log)
    rows = []
    for line in block[1].splitlines():
        m = re.match(r'^(\S+)\s+(\d+) s$', line.strip())
        if m:
            rows.append([m.group(1), m.group(2)])
    total = sum(int(r[1]) for r in rows)
    rows.append(['all stages', '%d (%.0f min)' % (total, total / 60.0)])
    chroot = []
    for m in re.finditer(r'=== sdk-chroot: (\S+) (ready|build|tests) in (\d+) s', text):
        chroot.append([m.group(1), {'ready': 'chroot set-up (made or reused)', 'build': 'configure and build',
                                    'tests': 'CTest suite'}[m.group(2)], m.group(3)])
    stamp = datetime.datetime.fromtimestamp(os.path.getmtime(opts.test_log), datetime.timezone.utc)
    out = provenance(stamp.strftime('%Y-%m-%d %H:%M UTC') + ' (the log\'s modification time)',
                     'the machine that ran it (the log does not record it)', ['bash scripts/test.sh 2>&1 | tee LOG', command_line(
                         ['/usr/bin/python3', 'scripts/results.py', '--only', 'stages',
                          '--test-log', 'LOG'])])
    out += ['Wall time of each stage as `scripts/test.sh` prints it at the end (an `sdk-*`',
            'stage counts what it waited for its chroot, set up in the background of the host',
            'stages):', '']
    out += table(['stage', 'seconds'], rows)
    if chroot:
        out += ['The chroot stages\' parts, from `scripts/sdk-chroot.sh`\'s lines in the log:', '']
        out += table(['release', 'part', 'seconds'], chroot, ['---', '---', '---:'])
    return out


FUZZ_HEADER = ['target', 'executions', 'findings', 'how it ended', 'executions/s', 'seed', 'when',
               'source']


def fuzz_row(target, path, commit):
    """One row of the fuzz table from a libFuzzer log (-print_final_stats=1)."""
    with open(path, errors='replace') as f:
        text = f.read()
    stats = dict(re.findall(r'^stat::(\w+):\s+(\d+)', text, re.M))
    if 'number_of_executed_units' not in stats:
        raise SystemExit('results: no final stats in %s (run with -print_final_stats=1)' % path)
    findings = len(re.findall(r'^==\d+==ERROR|^SUMMARY: |deadly signal|^ALARM: ', text, re.M))
    seed = re.search(r'^INFO: Seed: (\d+)', text, re.M)
    stamp = datetime.datetime.fromtimestamp(os.path.getmtime(path), datetime.timezone.utc)
    if findings:
        ended = 'a finding'
    elif re.search(r'^Done \d+ runs', text, re.M):
        ended = 'all runs done'
    elif 'run interrupted' in text:
        ended = 'stopped by hand'
    else:
        ended = '?'
    return [target, stats['number_of_executed_units'], str(findings), ended,
            stats.get('average_exec_per_sec', '?'),
            seed.group(1) if seed else '?', stamp.strftime('%Y-%m-%d %H:%M UTC'), commit or git_commit() or '?']


def folded_endings(endings):
    """The pieces' endings in order, a run of equal ones said once with its count."""
    folded = []
    for ending in endings:
        if folded and folded[-1][0] == ending:
            folded[-1][1] += 1
        else:
            folded.append([ending, 1])
    return [e if n == 1 else '%s (%d pieces)' % (e, n) for e, n in folded]


def combined_fuzz_row(logs):
    """One row for the logs of one target, in the order given: the pieces of one
    run in one WORK folder (one after another or side by side) add up."""
    if len(logs) == 1:
        return logs[0]
    executions = sum(int(r[1]) for r in logs)
    # The speed over all of them: their seconds summed (unknown if one's is).
    known = all(r[4].isdigit() and int(r[4]) > 0 for r in logs)
    seconds = sum(int(r[1]) / int(r[4]) for r in logs) if known else 0
    sources = list(dict.fromkeys(r[7] for r in logs))  # in the order of the runs
    return [logs[0][0], str(executions), str(sum(int(r[2]) for r in logs)),
            ', then '.join(folded_endings(r[3] for r in logs)),
            str(round(executions / seconds)) if seconds else '?',
            ', '.join(r[5] for r in logs), logs[-1][6], ', '.join(sources)]


def git_commit():
    try:
        return subprocess.run(['git', '-C', ROOT, 'rev-parse', '--short', 'HEAD'], capture_output=True,
                              text=True, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        return None


def section_fuzz(opts, scratch):
    if not opts.fuzz_log:
        raise Skip('no --fuzz-log')
    rows = {}
    for line in old_sections(opts.output).get('fuzz') or []:
        cells = [c.strip() for c in line.strip().strip('|').split('|')]
        if len(cells) == len(FUZZ_HEADER) and cells[0].startswith('Fuzz'):
            rows[cells[0]] = cells
    runs = {}
    for item in opts.fuzz_log:
        target, _, path = item.partition('=')
        path, _, commit = path.partition('@')
        if not target or not path:
            raise SystemExit('results: --fuzz-log wants TARGET=FILE[@COMMIT], not %s' % item)
        runs.setdefault(target, []).append(fuzz_row(target, path, commit))
    for target, logs in runs.items():
        rows[target] = combined_fuzz_row(logs)
    out = provenance(now(), machine(load=False), [
        'bash scripts/sanitize.sh asan   (the fuzzers, ASan + UBSan, in _build/asan)',
        'cd _build/asan && bin/TARGET -seed=SEED -runs=1000000 -timeout=30 -rss_limit_mb=2048 '
        '-print_final_stats=1 WORK ../../Testing/Fuzz/corpus/TARGET > LOG 2>&1',
        command_line(['/usr/bin/python3', 'scripts/results.py', '--only', 'fuzz', '--fuzz-log', 'TARGET=LOG'])])
    out += ['Runs by hand, far longer than the minute per target of the test suite: each from',
            'its committed seed corpus into an empty WORK folder, on one core, under ASan and',
            'UBSan (a finding stops the run). Findings: sanitizer reports, crashes, timeouts',
            'and out-of-memory stops in the log. Source: the commit the fuzzers were built',
            'from (TARGET=LOG@COMMIT), else the one the page was made at. A target given',
            'several logs is one run in pieces: each piece a new seed in the same WORK folder,',
            'after the piece before or beside it, from the corpus grown so far; their',
            'executions add up.', '']
    out += table(FUZZ_HEADER, [rows[k] for k in sorted(rows)],
                 ['---', '---:', '---:', '---', '---:', '---:', '---', '---'])
    return out


BUILDERS = {'sampler': section_sampler, 'parts': section_parts, 'pvpython': section_pvpython, 'peers': section_peers,
            'spectrum': section_spectrum, 'streaming': section_streaming, 'mpi': section_mpi,
            'quality': section_quality, 'stages': section_stages, 'fuzz': section_fuzz}


# --- the page ----------------------------------------------------------------

def old_sections(path):
    """The sections of an existing page, by name (their lines, marker excluded)."""
    found = {}
    try:
        with open(path) as f:
            lines = f.read().splitlines()
    except OSError:
        return found
    name = None
    for line in lines:
        m = re.fullmatch(r'<!-- section: (\w+) -->', line)
        if m:
            name = m.group(1)
            found[name] = []
        elif name:
            found[name].append(line)
    return found


def page(sections, argv):
    lines = ['# Results', '',
             '<!-- Generated by scripts/results.py; do not edit by hand. -->',
             'Generated by `scripts/results.py`, last by', '',
             '    ' + command_line(argv), '',
             'on %s. Do not edit by hand: `/usr/bin/python3 scripts/results.py --help` says how' % now(),
             'to regenerate the page or one section of it. Each section says when and on what',
             'machine it was made and the exact command that made it (run from the repository',
             'root; the benchmark programs\' JSON goes to a scratch folder). Times are wall-clock;',
             'on a machine shared with other jobs the ratios measured within one run (x_tight,',
             'vs_ED, speed-up) mean more than the absolute times. (Google Benchmark\'s warning',
             'that its library was built as DEBUG is about Debian\'s libbenchmark, not the timed',
             'code: each section names the build type of its programs.)', '']
    quick = [s for s in SECTIONS if any(l.startswith('- Mode: quick') for l in sections.get(s) or [])]
    if quick:
        lines += ['**Quick sections** (%s):' % ', '.join(quick),
                  'the smallest cases, once each, made to check the programs and this script, not',
                  'figures to quote; the full run (no `--quick`) measures every case with repetitions.', '']
    lines += ['- [%s](#%s)' % (TITLES[s], anchor(TITLES[s])) for s in SECTIONS]
    lines.append('')
    for s in SECTIONS:
        lines.append(MARK % s)
        body = sections.get(s)
        if body is None:
            body = ['## ' + TITLES[s], '', 'Not measured yet: `/usr/bin/python3 scripts/results.py'
                    ' --only %s%s`.' % (s, {'stages': ' --test-log LOG',
                                          'fuzz': ' --fuzz-log TARGET=LOG'}.get(s, '')), '']
        lines += body
    while lines and not lines[-1]:
        lines.pop()
    return '\n'.join(lines) + '\n'


def anchor(title):
    return re.sub(r'[^a-z0-9 _-]', '', title.lower()).replace(' ', '-')


def main():
    parser = argparse.ArgumentParser(
        description=__doc__.split('\n\n')[0].strip(),
        epilog=__doc__.split('\n\n', 2)[2], formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument('build', nargs='?', metavar='BUILD_DIR', default=os.path.join(ROOT, '_build', 'paraview'),
                        help='the build folder with the benchmark programs (default _build/paraview)')
    parser.add_argument('--quick', action='store_true',
                        help='the smallest cases, once: a check of the script, not figures to quote')
    parser.add_argument('--only', default=','.join(SECTIONS),
                        help='comma-separated sections to regenerate (default: all): ' + ', '.join(SECTIONS))
    parser.add_argument('--quality', action='store_true',
                        help='remake Testing/QualityReport.md first (scripts/quality-report.sh, ~20 min)')
    parser.add_argument('--test-log', help='a saved log of `bash scripts/test.sh` for the stages section')
    parser.add_argument('--fuzz-log', action='append', metavar='TARGET=FILE[@COMMIT]',
                        help='a libFuzzer log of TARGET (built from COMMIT) for the fuzz section (repeatable)')
    parser.add_argument('--streaming-edges', default='1024',
                        help='the volume edges of the streaming section (default 1024; 2048 takes 8 GiB of disk)')
    parser.add_argument('--pvpython', help='the pvpython to use (default: from PATH)')
    parser.add_argument('--pvbatch', help='the pvbatch to use (default: from PATH)')
    parser.add_argument('--output', default=os.path.join(ROOT, 'Documentation', 'Results.md'),
                        help='the page to write (default Documentation/Results.md)')
    opts = parser.parse_args()
    only = [s.strip() for s in opts.only.split(',') if s.strip()]
    unknown = [s for s in only if s not in SECTIONS]
    if unknown:
        parser.error('unknown section(s): %s (known: %s)' % (', '.join(unknown), ', '.join(SECTIONS)))
    if not os.path.isdir(opts.build):
        parser.error('no build folder %s' % opts.build)
    argv = ['/usr/bin/python3', 'scripts/results.py'] + [
        shown(a) if os.path.exists(a) and os.path.isabs(a) else a for a in sys.argv[1:]]
    sections = {k: v for k, v in old_sections(opts.output).items() if k in SECTIONS}
    start = time.monotonic()
    with tempfile.TemporaryDirectory(prefix='bluenoise-results.') as scratch:
        for s in only:
            begun = time.monotonic()
            try:
                body = BUILDERS[s](opts, scratch)
            except Skip as why:
                print('results: %s kept as it was (%s)' % (s, why), file=sys.stderr)
                continue
            sections[s] = ['## ' + TITLES[s], ''] + body
            print('results: %s done in %.0f s' % (s, time.monotonic() - begun), file=sys.stderr)
    os.makedirs(os.path.dirname(os.path.abspath(opts.output)), exist_ok=True)
    partial = opts.output + '.partial'
    with open(partial, 'w') as f:
        f.write(page(sections, argv))
    os.replace(partial, opts.output)
    print('results: wrote %s in %.0f s' % (opts.output, time.monotonic() - start), file=sys.stderr)


if __name__ == '__main__':
    main()
