#!/usr/bin/python3
"""check_layers.py — fails when a file includes a file of a layer it may not use.

usage: check_layers.py [--root DIR] [--table FILE] [--stamp FILE]

Reads the layer table (default DIR/tools/layers.txt: `layer folders... : uses...`, lowest
layer first), then every .h/.cpp file under the table's folders. A quoted include that names
a file of the tree (from DIR, else from the including file's folder) must lie in the same
layer or in one the including layer uses, directly or through the layers it uses. Also fails
when the table is malformed (unknown layer, a use of a layer listed later, a folder twice)
or when a folder under mesher/ belongs to no layer. Prints one line per violation
(file:line: ...) and exits 1; exits 0 and touches --stamp when the tree keeps its layers.
"""
import argparse
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s*"([^"]+)"')
SOURCE_SUFFIXES = ('.h', '.hpp', '.cpp')


def read_table(path):
    """[(layer, [folders], [uses])] in file order; raises ValueError on a malformed table."""
    layers = []
    seen_folders = {}
    with open(path, encoding='utf-8') as f:
        for number, raw in enumerate(f, 1):
            line = raw.split('#', 1)[0].strip()
            if not line:
                continue
            if ':' not in line:
                raise ValueError(f'{path}:{number}: expected "layer folders... : uses..."')
            left, right = line.split(':', 1)
            words = left.split()
            if len(words) < 2:
                raise ValueError(f'{path}:{number}: a layer needs a name and a folder')
            name, folders, uses = words[0], words[1:], right.split()
            known = {layer[0] for layer in layers}
            if name in known:
                raise ValueError(f'{path}:{number}: layer {name} listed twice')
            for use in uses:
                if use not in known:
                    raise ValueError(f'{path}:{number}: layer {name} uses {use}, '
                                     'which is not a layer listed before it')
            for folder in folders:
                folder = folder.rstrip('/')
                if folder in seen_folders:
                    raise ValueError(f'{path}:{number}: folder {folder} already in layer '
                                     f'{seen_folders[folder]}')
                seen_folders[folder] = name
            layers.append((name, [fo.rstrip('/') for fo in folders], uses))
    return layers


def allowed_layers(layers):
    """layer -> the set of layers its files may include: itself and the closure of its uses."""
    allowed = {}
    for name, _, uses in layers:  # lowest first: every use is already closed
        allowed[name] = {name}.union(*(allowed[u] for u in uses))
    return allowed


def layer_of(relpath, folders):
    """The layer of the longest table folder containing relpath, or None."""
    best, best_len = None, -1
    for folder, name in folders.items():
        if (relpath == folder or relpath.startswith(folder + '/')) and len(folder) > best_len:
            best, best_len = name, len(folder)
    return best


def resolve(root, including_dir, target):
    """The include's file relative to root ('/'-separated), or None when not in the tree."""
    for base in (root, os.path.join(root, including_dir)):
        candidate = os.path.normpath(os.path.join(base, target))
        if os.path.isfile(candidate):
            rel = os.path.relpath(candidate, root)
            if not rel.startswith('..'):
                return rel.replace(os.sep, '/')
    return None


def check(root, layers):
    """The violations, as printable lines."""
    folders = {folder: name for name, fs, _ in layers for folder in fs}
    allowed = allowed_layers(layers)
    problems = []
    mesher = os.path.join(root, 'mesher')
    if os.path.isdir(mesher):
        for entry in sorted(os.listdir(mesher)):
            rel = 'mesher/' + entry
            if os.path.isdir(os.path.join(root, rel)) and layer_of(rel, folders) is None:
                problems.append(f'{rel}: folder in no layer of the table')
            elif entry.endswith(SOURCE_SUFFIXES):
                problems.append(f'{rel}: file outside the layers\' folders')
    for folder in sorted(folders):
        for dirpath, dirnames, filenames in os.walk(os.path.join(root, folder)):
            dirnames.sort()
            for filename in sorted(filenames):
                if not filename.endswith(SOURCE_SUFFIXES):
                    continue
                path = os.path.join(dirpath, filename)
                rel = os.path.relpath(path, root).replace(os.sep, '/')
                layer = layer_of(rel, folders)
                with open(path, encoding='utf-8', errors='replace') as f:
                    for number, line in enumerate(f, 1):
                        match = INCLUDE.match(line)
                        if not match:
                            continue
                        target = resolve(root, os.path.dirname(rel), match.group(1))
                        target_layer = layer_of(target, folders) if target else None
                        if target_layer is None or target_layer in allowed[layer]:
                            continue
                        problems.append(f'{rel}:{number}: includes {target} (layer '
                                        f'{target_layer}); layer {layer} may use only '
                                        f'{", ".join(sorted(allowed[layer]))}')
    return problems


def main():
    parser = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    here = os.path.dirname(os.path.abspath(__file__))
    parser.add_argument('--root', default=os.path.dirname(here))
    parser.add_argument('--table')
    parser.add_argument('--stamp')
    args = parser.parse_args()
    root = os.path.abspath(args.root)
    table = args.table or os.path.join(root, 'tools', 'layers.txt')
    try:
        layers = read_table(table)
    except (OSError, ValueError) as e:
        print(f'check_layers: {e}', file=sys.stderr)
        return 1
    problems = check(root, layers)
    for p in problems:
        print(p, file=sys.stderr)
    if problems:
        print(f'check_layers: {len(problems)} include(s) break the layers of {table}',
              file=sys.stderr)
        return 1
    if args.stamp:
        with open(args.stamp, 'w', encoding='utf-8') as f:
            f.write('layers ok\n')
    return 0


if __name__ == '__main__':
    sys.exit(main())
