#!/usr/bin/python3
"""bench:sizes (bench/sizes.sh runs this): meshes sized for a solver, acutemesh next to Gmsh.

For each input (.poly) and size (uniform, or a graded function of distance to a point), runs
  - `build/acutemesh --mode quality|nonobtuse|acute --max-edge H` or `--size GRID.json`
    (the function sampled on a 1-unit grid, bilinear), with --stats;
  - Gmsh 2D (`gmsh -2 -nt 1`, its default Frontal-Delaunay) on a .geo of the same domain, with
    Mesh.MeshSizeMax = H, or a MathEval background field of the same function,
  - with $SIZES_OPTIMIZE seconds (default 5; 0 leaves these rows out): quality mode at
    --min-angle 30 (and 33: QUALITY_ANGLES) with the same sizes, without and with --optimize,
and measures every mesh here, the same way (meshio reads Gmsh's .msh; acutemesh writes .msh
too): triangles, vertices, wall seconds, smallest and largest angle, triangles with an angle
of 90 or more, and the size ratio (the largest longest-edge / size at the centroid: <= 1 means
every edge is within its size). Writes bench/results/sizes-YYYY-MM-DD.md and prints it.
"""
import datetime
from fractions import Fraction
import json
import math
import os
import platform
import subprocess
import sys
import time

import meshio

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WORK = os.path.join(ROOT, 'bench', 'work', 'sizes')
CLI = os.path.join(ROOT, 'build', 'acutemesh')
GMSH_SHRINK = 1.45
OPTIMIZE = float(os.environ.get('SIZES_OPTIMIZE', '5'))
QUALITY_ANGLES = [30, 33]


def read_poly(path):
    """Points, segments and holes of a Triangle .poly (vertices in the file)."""
    rows = []
    with open(path) as f:
        for line in f:
            line = line.split('#', 1)[0].split()
            if line:
                rows.append(line)
    n = int(rows[0][0])
    points = [(float(r[1]), float(r[2])) for r in rows[1:1 + n]]
    first = int(rows[1][0])
    m = int(rows[1 + n][0])
    segments = [(int(r[1]) - first, int(r[2]) - first) for r in rows[2 + n:2 + n + m]]
    h = int(rows[2 + n + m][0])
    holes = [(float(r[1]), float(r[2])) for r in rows[3 + n + m:3 + n + m + h]]
    return points, segments, holes


def rings(segments):
    """The segments as closed loops of point indices (every vertex on two segments)."""
    nxt = {}
    for a, b in segments:
        nxt.setdefault(a, []).append(b)
        nxt.setdefault(b, []).append(a)
    seen, loops = set(), []
    for start in nxt:
        if start in seen:
            continue
        loop, prev, v = [start], None, start
        seen.add(start)
        while True:
            w = next(u for u in nxt[v] if u != prev) if prev is not None else nxt[v][0]
            if w == start:
                break
            loop.append(w)
            seen.add(w)
            prev, v = v, w
        loops.append(loop)
    return loops


def write_geo(path, points, segments, size_line):
    loops = rings(segments)
    area = lambda loop: sum(points[a][0] * points[b][1] - points[b][0] * points[a][1]
                            for a, b in zip(loop, loop[1:] + loop[:1])) / 2
    loops.sort(key=lambda loop: -abs(area(loop)))  # the outline first, then the holes
    with open(path, 'w') as f:
        for i, (x, y) in enumerate(points):
            f.write(f'Point({i + 1}) = {{{x!r}, {y!r}, 0}};\n')
        line = 0
        for k, loop in enumerate(loops):
            ids = []
            for a, b in zip(loop, loop[1:] + loop[:1]):
                line += 1
                f.write(f'Line({line}) = {{{a + 1}, {b + 1}}};\n')
                ids.append(str(line))
            f.write(f'Curve Loop({k + 1}) = {{{", ".join(ids)}}};\n')
        f.write(f'Plane Surface(1) = {{{", ".join(str(k + 1) for k in range(len(loops)))}}};\n')
        f.write('Mesh.MeshSizeFromPoints = 0;\nMesh.MeshSizeFromCurvature = 0;\n')
        f.write('Mesh.MeshSizeExtendFromBoundary = 0;\n')
        f.write(size_line)


def acute_corner(a, b, c):
    """The angle at a is below 90: the dot product's sign, exact (the coordinates are doubles,
    which Fraction holds exactly) where floating point cannot tell."""
    ux, uy, vx, vy = b[0] - a[0], b[1] - a[1], c[0] - a[0], c[1] - a[1]
    d = ux * vx + uy * vy
    if abs(d) > 1e-9 * (abs(ux * vx) + abs(uy * vy)):
        return d > 0
    F = [Fraction(float(t)) for t in (a[0], a[1], b[0], b[1], c[0], c[1])]
    return (F[2] - F[0]) * (F[4] - F[0]) + (F[3] - F[1]) * (F[5] - F[1]) > 0


def measure(path, size):
    """Figures of the triangles in a mesh file, sizes measured against size(x, y)."""
    m = meshio.read(path)
    pts = m.points
    tris = [c.data for c in m.cells if c.type == 'triangle']
    used = set()
    count, worst, lo, hi, non_acute = 0, 0.0, 180.0, 0.0, 0
    for block in tris:
        for t in block:
            count += 1
            used.update(int(v) for v in t)
            p = [pts[int(v)][:2] for v in t]
            e = [math.dist(p[(k + 1) % 3], p[(k + 2) % 3]) for k in range(3)]  # opposite corner k
            for k in range(3):
                a, b, c = e[k], e[(k + 1) % 3], e[(k + 2) % 3]
                cosine = max(-1.0, min(1.0, (b * b + c * c - a * a) / (2 * b * c)))
                angle = math.degrees(math.acos(cosine))
                lo, hi = min(lo, angle), max(hi, angle)
            if any(not acute_corner(p[k], p[(k + 1) % 3], p[(k + 2) % 3]) for k in range(3)):
                non_acute += 1
            cx, cy = sum(q[0] for q in p) / 3, sum(q[1] for q in p) / 3
            worst = max(worst, max(e) / size(cx, cy))
    return {'triangles': count, 'vertices': len(used), 'min': lo, 'max': hi,
            'nonAcute': non_acute, 'ratio': worst}


def run(cmd):
    t = time.perf_counter()
    r = subprocess.run(cmd, capture_output=True, text=True)
    return time.perf_counter() - t, r


def main():
    shared = os.environ.get('ACUTEMESH_DATA', os.path.join(ROOT, '..', 'shared', 'data'))
    os.makedirs(WORK, exist_ok=True)
    inputs = [('plate (200 x 100, 3 holes, a slot)', os.path.join(ROOT, 'tests', 'data', 'plate.poly'),
               [4, 1], (100, 50, 1, 0.1, 8))]
    superior = os.path.join(shared, 'poly', 'superior.poly')
    skipped = []
    if os.path.exists(superior):
        inputs.append(('Lake Superior (outline and islands)', superior, [0.5, 0.1], None))
    else:
        skipped.append(f'Lake Superior skipped: {superior} not found (../shared/data)')
    gmsh = subprocess.run(['sh', '-c', 'command -v gmsh'], capture_output=True, text=True).stdout.strip()
    rows = []
    for label, path, uniform, graded in inputs:
        points, segments, holes = read_poly(path)
        xs, ys = [p[0] for p in points], [p[1] for p in points]
        box = (min(xs), min(ys), max(xs), max(ys))
        cases = [(f'max edge {h}', h, None) for h in uniform]
        if graded:
            cx, cy, h0, g, hmax = graded
            cases.append((f'graded: {h0} + {g} x distance to ({cx}, {cy}), at most {hmax}', None, graded))
        for case, h, graded_case in cases:
            base = os.path.join(WORK, os.path.basename(path).replace('.poly', '') + '-' +
                                (f'h{h}' if h else 'graded'))
            if h:
                size = lambda x, y, h=h: h
                ours_size = ['--max-edge', str(h)]
                gmsh_size = lambda k, h=h: f'Mesh.MeshSizeMax = {h / k};\nMesh.MeshSizeMin = {h / k};\n'
            else:
                cx, cy, h0, g, hmax = graded_case
                size = lambda x, y: min(hmax, h0 + g * math.hypot(x - cx, y - cy))
                nx, ny = int(box[2] - box[0]) + 2, int(box[3] - box[1]) + 2
                grid = {'x0': box[0], 'y0': box[1], 'dx': 1, 'dy': 1, 'nx': nx, 'ny': ny,
                        'h': [size(box[0] + i, box[1] + j) for j in range(ny) for i in range(nx)]}
                with open(base + '.size.json', 'w') as f:
                    json.dump({'grid': grid}, f)
                ours_size = ['--size', base + '.size.json']
                gmsh_size = lambda k: (f'Field[1] = MathEval;\nField[1].F = "Min({hmax}, {h0} + {g} * '
                                       f'Sqrt((x - {cx})^2 + (y - {cy})^2)) / {k}";\nBackground Field = 1;\n')
            # (mode, options besides the sizes, the file name's suffix)
            runs = [(mode, [], mode) for mode in ['quality', 'nonobtuse', 'acute']]
            if OPTIMIZE > 0:
                runs += [('quality', ['--min-angle', str(a)], f'quality{a}') for a in QUALITY_ANGLES]
                runs += [('quality', ['--min-angle', str(a), '--optimize', f'{OPTIMIZE:g}'],
                          f'quality{a}-opt') for a in QUALITY_ANGLES]
            for mode, extra, name in runs:
                tool = ' '.join(['acutemesh', mode, *extra])
                out = f'{base}-{name}'
                seconds, r = run([CLI, '--mode', mode, *ours_size, *extra, '--stats', '--threads', '1',
                                  '--format', 'msh', '-o', out, path])
                stats = json.loads(r.stdout) if r.stdout.strip() else {}
                row = {'input': label, 'case': case, 'tool': tool, 'seconds': seconds,
                       'status': stats.get('status', f'exit {r.returncode}'),
                       'certified': stats.get('certified')}
                if r.returncode in (0, 1):
                    row.update(measure(out + '.msh', size))
                rows.append(row)
            # Gmsh aims at edges of the size on average, so some are longer: it also runs with
            # the size divided by GMSH_SHRINK, which brings its longest edges within the size.
            for shrink in ([1, GMSH_SHRINK] if gmsh else []):
                geo = f'{base}-gmsh{shrink}.geo'
                write_geo(geo, points, segments, gmsh_size(shrink))
                seconds, r = run([gmsh, '-2', '-nt', '1', '-v', '2', '-format', 'msh41', '-o', geo + '.msh', geo])
                tool = 'Gmsh 2D (Frontal-Delaunay)' + (f', size / {shrink}' if shrink != 1 else '')
                row = {'input': label, 'case': case, 'tool': tool,
                       'seconds': seconds, 'status': 'ok' if r.returncode == 0 else f'exit {r.returncode}'}
                if r.returncode == 0:
                    row.update(measure(geo + '.msh', size))
                rows.append(row)
    # The README's solver example, a size file of scattered points, against the plate meshed
    # uniformly at its smallest size: what grading the sizes saves (figures from --stats).
    plate = os.path.join(ROOT, 'tests', 'data', 'plate.poly')
    for case, args in [('README: --size tests/data/sizes/plate.json --grading 0.2 (0.5 at the left hole)',
                        ['--size', os.path.join(ROOT, 'tests', 'data', 'sizes', 'plate.json'), '--grading', '0.2']),
                       ('uniform at that smallest size: max edge 0.5', ['--max-edge', '0.5'])]:
        seconds, r = run([CLI, '--mode', 'acute', *args, '--stats', '--threads', '1', '--no-output', plate])
        st = json.loads(r.stdout) if r.stdout.strip() else {}
        row = {'input': 'plate (200 x 100, 3 holes, a slot)', 'case': case, 'tool': 'acutemesh acute',
               'seconds': seconds, 'status': st.get('status', f'exit {r.returncode}'),
               'certified': st.get('certified')}
        if st:
            row.update({'triangles': st['triangles'], 'vertices': st['vertices'], 'min': st['minAngle'],
                        'max': st['maxAngle'], 'nonAcute': st['nonAcute'], 'ratio': st['sizeRatio']})
        rows.append(row)
    if not gmsh:
        skipped.append('Gmsh not installed: no peer rows (apt install gmsh)')
    gmsh_version = subprocess.run([gmsh, '--version'], capture_output=True, text=True).stderr.strip() if gmsh else 'none'
    cpu = next((l.split(':', 1)[1].strip() for l in open('/proc/cpuinfo') if l.startswith('model name')), platform.machine())
    today = datetime.date.today().isoformat()
    lines = [f'# Sizes for solvers: acutemesh and Gmsh ({today})', '',
             f'Machine: {cpu}, {os.cpu_count()} cores, {platform.system()} {platform.release()}; '
             f'acutemesh --threads 1, Gmsh {gmsh_version} -nt 1. `npm run bench:sizes`'
             + (f' (SIZES_OPTIMIZE={OPTIMIZE:g})' if OPTIMIZE != 5 else '') + '.', '',
             'Every mesh measured here the same way (meshio reads the .msh files): size ratio = the '
             'largest longest-edge over the size at the centroid (<= 1: every edge within its size); '
             '"≥ 90°" counts triangles with an angle of 90 or more (by the exact sign of a dot product). Seconds: wall time of the whole '
             'command (reading, meshing, writing .msh). The last two rows (the README example '
             'and the uniform mesh it saves) take their figures from --stats.', '']
    for s in skipped:
        lines.append(f'- {s}')
    if skipped:
        lines.append('')
    lines += ['| input | size | tool | status | triangles | vertices | seconds | min angle | max angle | ≥ 90° | size ratio |',
              '|---|---|---|---|---:|---:|---:|---:|---:|---:|---:|']
    for r in rows:
        status = r['status'] + (', certified' if r.get('certified') else '')
        if 'triangles' not in r:
            lines.append(f"| {r['input']} | {r['case']} | {r['tool']} | {status} | | | {r['seconds']:.2f} | | | | |")
            continue
        lines.append(f"| {r['input']} | {r['case']} | {r['tool']} | {status} | {r['triangles']:,} | "
                     f"{r['vertices']:,} | {r['seconds']:.2f} | {r['min']:.1f} | {r['max']:.2f} | "
                     f"{r['nonAcute']:,} | {r['ratio']:.3f} |")
    os.makedirs(os.path.join(ROOT, 'bench', 'results'), exist_ok=True)
    # (bench/common.sh's report_path rule: a report of the same day is kept, this one is -2, -3...)
    out, k = os.path.join(ROOT, 'bench', 'results', f'sizes-{today}.md'), 2
    while os.path.exists(out):
        out, k = os.path.join(ROOT, 'bench', 'results', f'sizes-{today}-{k}.md'), k + 1
    with open(out, 'w') as f:
        f.write('\n'.join(lines) + '\n')
    print('\n'.join(lines))
    print(f'\nwritten: {os.path.relpath(out, ROOT)}', file=sys.stderr)


if __name__ == '__main__':
    main()
