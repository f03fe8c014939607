#!/usr/bin/python3
"""tools/check_layers.py on small trees made here: a tree that keeps its layers passes (and
gets its stamp); an upward include (from the root, relative, from a header), a folder of
mesher/ in no layer and a table that uses a later layer fail, naming the file and line.
usage: check_layers_test.py SOURCE_DIR"""
import os
import shutil
import subprocess
import sys
import tempfile

SOURCE = os.path.abspath(sys.argv[1])
CHECK = os.path.join(SOURCE, 'tools', 'check_layers.py')
TABLE = 'core mesher/core :\nmodel mesher/model : core\nsurface mesher/surface : model\n'
failures = []
roots = []


def tree(files, table=TABLE):
    """A temporary tree holding `files` (path -> text) and the table tools/layers.txt."""
    root = tempfile.mkdtemp(prefix='layers_')
    roots.append(root)
    files = dict(files)
    files['tools/layers.txt'] = table
    for path, text in files.items():
        os.makedirs(os.path.join(root, os.path.dirname(path)), exist_ok=True)
        with open(os.path.join(root, path), 'w', encoding='utf-8') as f:
            f.write(text)
    return root


def run(root, *extra):
    p = subprocess.run(['/usr/bin/python3', CHECK, '--root', root, *extra],
                       capture_output=True, text=True)
    return p.returncode, p.stderr


def expect(name, root, code, text='', *extra):
    rc, err = run(root, *extra)
    if rc != code or text not in err:
        failures.append(f'{name}: exit {rc} (want {code}), stderr:\n{err}')


GOOD = {
    'mesher/core/A.h': '#pragma once\nint a();\n',
    'mesher/core/A.cpp': '#include "mesher/core/A.h"\nint a() { return 1; }\n',
    'mesher/model/M.h': '#pragma once\n#include <vector>\n#include "mesher/core/A.h"\n',
    'mesher/surface/sub/S.cpp': '#include "mesher/model/M.h"\n#include "../../core/A.h"\n',
}
good = tree(GOOD)
stamp = os.path.join(good, 'stamp')
expect('downward includes', good, 0, '', '--stamp', stamp)
if not os.path.isfile(stamp):
    failures.append('downward includes: no stamp written')

bad = dict(GOOD)
bad['mesher/core/A.h'] = '#pragma once\n\n#include "mesher/surface/sub/S.h"\n'
bad['mesher/surface/sub/S.h'] = '#pragma once\n'
expect('upward include from the root', tree(bad), 1,
       'mesher/core/A.h:3: includes mesher/surface/sub/S.h (layer surface)')

bad = dict(GOOD)
bad['mesher/model/M.cpp'] = '#include "../surface/sub/S.cpp"\n'
expect('relative upward include', tree(bad), 1, 'mesher/model/M.cpp:1: includes mesher/surface')

bad = dict(GOOD)
bad['mesher/extra/E.cpp'] = '#include "mesher/core/A.h"\n'
expect('folder in no layer', tree(bad), 1, 'mesher/extra: folder in no layer')

expect('table using a later layer', tree(GOOD, TABLE + 'metric mesher/metric : pipeline\n'),
       1, 'which is not a layer listed before it')

# The project's own table: the mesher's lowest layer may not include its highest.
real = tree({'mesher/core/Bad.h': '#pragma once\n#include "mesher/pipeline/Pipeline.h"\n',
             'mesher/pipeline/Pipeline.h': '#pragma once\n'})
expect('the project table rejects core -> pipeline', real, 1, 'mesher/core/Bad.h:2', '--table',
       os.path.join(SOURCE, 'tools', 'layers.txt'))

for r in roots:
    shutil.rmtree(r)
for f in failures:
    print(f)
print('check_layers_test:', 'FAILED' if failures else 'ok')
sys.exit(1 if failures else 0)
