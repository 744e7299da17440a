# SPDX-FileCopyrightText: Copyright (c) 2025-2026 the BlueNoiseSampling contributors
# SPDX-License-Identifier: BSD-3-Clause
"""The user documentation against the tree it describes (plain Python, no VTK).

    python3 TestDocumentation.py --source SOURCE_DIR

Checks README.md and Documentation/*.md:
  - every relative Markdown link names a file that exists, and a #fragment
    names a heading of the linked page (GitHub's anchors);
  - every repository path in `code` (a word whose first part is a top-level
    entry of the tree, like Testing/... or scripts/...) exists;
  - the README keeps its two set-up commands, `bash scripts/main.sh` and
    `bash scripts/test.sh`, as indented lines of their own (.ci/run runs the
    second);
  - scripts/results.py --help runs (stdlib only, no build needed).
Exit status 1 with one line per problem.
"""
import argparse
import glob
import os
import re
import subprocess
import sys


def anchors(path):
    """GitHub's anchors of a Markdown file's headings."""
    found = set()
    with open(path) as f:
        for line in f:
            m = re.match(r'^#+ (.*)$', line.rstrip('\n'))
            if m:
                found.add(re.sub(r'[^a-z0-9 _-]', '', m.group(1).strip().lower()).replace(' ', '-'))
    return found


def check_file(source, path, problems):
    top = {e for e in os.listdir(source) if not e.startswith('_') and e not in ('.git', 'build')}
    here = os.path.dirname(path)
    name = os.path.relpath(path, source)
    with open(path) as f:
        text = f.read()
    # Code blocks are commands and programs, not paths to check.
    prose = re.sub(r'^(    |      ).*$', '', text, flags=re.M)
    for target in re.findall(r'\]\(([^)\s]+)\)', prose):
        if re.match(r'[a-z]+:', target):
            continue
        file_part, _, fragment = target.partition('#')
        linked = os.path.normpath(os.path.join(here, file_part)) if file_part else path
        if not os.path.exists(linked):
            problems.append('%s: link to %s: no such file' % (name, target))
        elif fragment and linked.endswith('.md') and fragment not in anchors(linked):
            problems.append('%s: link to %s: no heading with that anchor' % (name, target))
    for code in re.findall(r'`([^`]+)`', prose):
        for word in code.split():
            word = word.strip('(),;:"\'')
            first = word.split('/', 1)[0]
            if first not in top or ('/' not in word and not os.path.isfile(os.path.join(source, word))):
                continue
            if any(c in word for c in '<>|=') or 'RELEASE' in word or '...' in word:
                continue
            if not glob.glob(os.path.join(source, word)):
                problems.append('%s: `%s` names no file of the tree' % (name, word))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    parser.add_argument('--source', required=True)
    args = parser.parse_args()
    source = os.path.abspath(args.source)
    problems = []
    pages = [os.path.join(source, 'README.md')] + sorted(
        glob.glob(os.path.join(source, 'Documentation', '*.md')))
    for page in pages:
        check_file(source, page, problems)
    with open(os.path.join(source, 'README.md')) as f:
        lines = f.read().splitlines()
    for command in ('bash scripts/main.sh', 'bash scripts/test.sh'):
        if '    ' + command not in lines:
            problems.append('README.md: the set-up command `%s` is not a line of its own' % command)
    done = subprocess.run([sys.executable, os.path.join(source, 'scripts', 'results.py'), '--help'],
                          capture_output=True, text=True)
    if done.returncode != 0 or 'usage' not in done.stdout:
        problems.append('scripts/results.py --help: exit status %d\n%s' % (done.returncode, done.stderr))
    for p in problems:
        print(p)
    print('%d page(s) checked, %d problem(s)' % (len(pages), len(problems)))
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main())
