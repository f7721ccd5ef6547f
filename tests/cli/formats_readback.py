#!/usr/bin/python3
"""The solver formats read back by an independent reader (Debian's python3-meshio, which
scripts/setup.sh installs), and Triangle's .edge/.neigh checked by a parser of their own.

usage: /usr/bin/python3 formats_readback.py ACUTEMESH DATA_DIR

For each fixture the CLI meshes it (acute) into .node/.ele/.edge/.neigh/.msh/.v2.msh/.vtu;
then: meshio (and Gmsh's -check, when gmsh is installed) reads the MSH 4.1, MSH 2.2 and VTU files and finds the same points (exactly, as
doubles), the same triangles, and physical groups / cell data that say what .node, .ele and
.edge say (vertex markers, region attributes, edge markers); every boundary edge is a line.
A missing meshio is a failure: setup installs it.
"""
import math
import os
import shutil
import subprocess
import sys
import tempfile
import warnings

failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL: " + what)


def lines_of(path):
    with open(path) as f:
        return [l.split() for l in f if l.strip() and not l.lstrip().startswith("#")]


def read_node(path):
    rows = lines_of(path)
    n, dim, attrs, markers = map(int, rows[0])
    assert (dim, attrs, markers) == (2, 0, 1), rows[0]
    points = [(float(r[1]), float(r[2])) for r in rows[1:1 + n]]
    vertex_markers = [int(r[3]) for r in rows[1:1 + n]]
    assert [int(r[0]) for r in rows[1:1 + n]] == list(range(n))
    return points, vertex_markers


def read_ele(path):
    rows = lines_of(path)
    t, corners, attrs = map(int, rows[0])
    assert corners == 3 and attrs in (0, 1), rows[0]
    triangles = [tuple(int(v) for v in r[1:4]) for r in rows[1:1 + t]]
    attributes = [float(r[4]) for r in rows[1:1 + t]] if attrs else None
    return triangles, attributes


def read_edge(path):
    rows = lines_of(path)
    e, markers = map(int, rows[0])
    assert markers == 1, rows[0]
    return {(int(r[1]), int(r[2])): int(r[3]) for r in rows[1:1 + e]}, e


def read_neigh(path):
    rows = lines_of(path)
    t, three = map(int, rows[0])
    assert three == 3, rows[0]
    return [tuple(int(v) for v in r[1:4]) for r in rows[1:1 + t]]


def key(a, b):
    return (min(a, b), max(a, b))


def check_triangle_files(name, triangles, edges, edge_count, neigh):
    """.edge and .neigh against the triangles, parsed here."""
    uses = {}
    for t, tri in enumerate(triangles):
        for k in range(3):
            uses.setdefault(key(tri[k], tri[(k + 1) % 3]), []).append(t)
    check(edge_count == len(edges) == len(uses),
          f"{name}.edge: {edge_count} lines, {len(edges)} distinct, the triangles have {len(uses)}")
    check(set(edges) == set(uses), f"{name}.edge: not the triangles' edges")
    for e, ts in uses.items():
        if len(ts) == 1:
            check(edges.get(e, 0) != 0, f"{name}.edge: boundary edge {e} has marker 0")
    check(len(neigh) == len(triangles), f"{name}.neigh: {len(neigh)} lines for {len(triangles)} triangles")
    for t, tri in enumerate(triangles):
        for k in range(3):
            n = neigh[t][k]
            e = key(tri[(k + 1) % 3], tri[(k + 2) % 3])  # the edge opposite corner k
            others = [u for u in uses[e] if u != t]
            check(n == (others[0] if others else -1), f"{name}.neigh: triangle {t} corner {k}: {n}, expected {others}")
            if n >= 0:
                check(t in neigh[n], f"{name}.neigh: {t} -> {n} but not back")


def physical_names(mesh):
    """meshio's field_data: name -> (tag, dim); as {(dim, tag): name}."""
    return {(int(v[1]), int(v[0])): k for k, v in mesh.field_data.items()}


def check_gmsh(name, path, points, vertex_markers, triangles, attributes, edges):
    import meshio
    import numpy as np
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        m = meshio.read(path)
    check(not caught, f"{path}: meshio warned: {[str(w.message) for w in caught]}")
    check(m.points.shape == (len(points), 3), f"{path}: points {m.points.shape}")
    check(np.array_equal(m.points[:, :2], np.array(points)) and not m.points[:, 2].any(),
          f"{path}: points differ from .node")
    names = physical_names(m)
    physical = m.cell_data["gmsh:physical"]
    got_triangles, lines = [], {}
    for block, tags in zip(m.cells, physical):
        for cell, tag in zip(block.data.tolist(), tags.tolist()):
            label = names.get((2 if block.type == "triangle" else 1, int(tag)))
            if block.type == "triangle":
                if attributes is None:
                    check(label == "domain", f"{path}: triangle in group {label}")
                    value = None
                else:
                    check(label is not None and label.startswith("attribute "), f"{path}: triangle in group {label}")
                    value = float(label.split()[1]) if label else math.nan
                got_triangles.append((tuple(cell), value))
            elif block.type == "line":
                marker = int(label.split()[1]) if label and label.startswith("marker ") else None
                check(marker is not None, f"{path}: line in physical group {tag} without a marker name")
                lines[key(*cell)] = marker
            else:
                check(False, f"{path}: unexpected cells {block.type}")
    want = [(t, None if attributes is None else attributes[i]) for i, t in enumerate(triangles)]
    check(sorted(got_triangles) == sorted(want), f"{path}: triangles or their attributes differ from .ele")
    for e, marker in lines.items():
        check(edges.get(e) == marker, f"{path}: line {e} marker {marker}, .edge says {edges.get(e)}")
    boundary = {e for e, n in count_uses(triangles).items() if n == 1}
    check(boundary <= set(lines), f"{path}: boundary edges not among the lines: {sorted(boundary - set(lines))[:5]}")


def count_uses(triangles):
    uses = {}
    for tri in triangles:
        for k in range(3):
            e = key(tri[k], tri[(k + 1) % 3])
            uses[e] = uses.get(e, 0) + 1
    return uses


def check_vtu(name, path, points, vertex_markers, triangles, attributes, edges):
    import meshio
    import numpy as np
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        m = meshio.read(path)
    check(not caught, f"{path}: meshio warned: {[str(w.message) for w in caught]}")
    check(np.array_equal(m.points[:, :2], np.array(points)) and not m.points[:, 2].any(),
          f"{path}: points differ from .node")
    check(m.point_data["marker"].tolist() == vertex_markers, f"{path}: point markers differ from .node")
    blocks = {b.type: i for i, b in enumerate(m.cells)}
    check(set(blocks) == {"triangle", "line"}, f"{path}: cell types {list(blocks)}")
    tri = blocks["triangle"]
    # VTU keeps the order: the triangles are .ele's, in order.
    check([tuple(c) for c in m.cells[tri].data.tolist()] == triangles, f"{path}: triangles differ from .ele")
    check(not m.cell_data["marker"][tri].any(), f"{path}: triangles with a marker")
    if attributes is None:
        check("attribute" not in m.cell_data, f"{path}: attributes without regions")
    else:
        check(m.cell_data["attribute"][tri].tolist() == attributes, f"{path}: attributes differ from .ele")
    line = blocks["line"]
    for cell, marker in zip(m.cells[line].data.tolist(), m.cell_data["marker"][line].tolist()):
        check(edges.get(key(*cell)) == marker, f"{path}: line {cell} marker {marker}, .edge says {edges.get(key(*cell))}")
    boundary = {e for e, n in count_uses(triangles).items() if n == 1}
    check(boundary <= {key(*c) for c in m.cells[line].data.tolist()}, f"{path}: boundary edges not among the lines")


def check_files(name, base):
    """The files BASE.node ... BASE.vtu, each against the others."""
    points, vertex_markers = read_node(base + ".node")
    triangles, attributes = read_ele(base + ".ele")
    edges, edge_count = read_edge(base + ".edge")
    neigh = read_neigh(base + ".neigh")
    check_triangle_files(name, triangles, edges, edge_count, neigh)
    for path in (base + ".msh", base + ".v2.msh"):
        check_gmsh(name, path, points, vertex_markers, triangles, attributes, edges)
    check_vtu(name, base + ".vtu", points, vertex_markers, triangles, attributes, edges)
    # Gmsh itself, when it is installed (Debian's gmsh; setup does not install it): both files
    # load and pass its coherence check without an error.
    if shutil.which("gmsh"):
        for path in (base + ".msh", base + ".v2.msh"):
            run = subprocess.run(["gmsh", "-nopopup", "-check", path], capture_output=True, text=True, timeout=120)
            errors = [l for l in (run.stdout + run.stderr).splitlines() if l.startswith("Error")]
            check(run.returncode == 0 and not errors, f"{path}: gmsh -check: exit {run.returncode} {errors}")
    # The MSH 4.1 header as the spec has it (meshio reads 2.2 files too).
    with open(base + ".msh") as f:
        check(f.read(40).startswith("$MeshFormat\n4.1 0 8\n"), f"{name}.msh: not MSH 4.1")
    print(f"read back: {name}: {len(points)} vertices, {len(triangles)} triangles, "
          f"{len(edges)} edges, attributes {'yes' if attributes else 'none'}"
          f"{'' if shutil.which('gmsh') else ' (gmsh not installed: meshio only)'}")
    return points, vertex_markers, triangles, attributes, edges


def main():
    acutemesh, data = sys.argv[1], sys.argv[2]
    try:
        import meshio  # noqa: F401
    except ImportError:
        print(f"FAIL: {sys.executable} has no meshio: run scripts/setup.sh (python3-meshio for /usr/bin/python3)")
        return 1
    with tempfile.TemporaryDirectory() as work:
        for fixture in ["plate.poly", "io/marked-regions.poly"]:
            name = os.path.splitext(os.path.basename(fixture))[0]
            base = os.path.join(work, name)
            run = subprocess.run([acutemesh, os.path.join(data, fixture), "--mode", "acute", "-o", base,
                                  "--format", "node,ele,edge,neigh,msh,msh2,vtu"],
                                 capture_output=True, text=True)
            check(run.returncode == 0, f"{fixture}: exit {run.returncode}: {run.stderr}")
            if run.returncode != 0:
                continue
            check_files(fixture, base)
        # Markers and attributes filled by hand (tests/cpp/test_formats.cpp writes these very
        # files): negative and zero markers, a fractional attribute, an unused vertex.
        marked = os.path.join(data, "io", "two-squares", "marked")
        points, vertex_markers, triangles, attributes, edges = check_files("two-squares", marked)
        check(vertex_markers == [5, 5, 1, -2, 7, 7, 0], f"two-squares.node: markers {vertex_markers}")
        check(attributes == [1, 1, 2.5, 2.5], f"two-squares.ele: attributes {attributes}")
        check(sorted(set(edges.values())) == [-2, 0, 1, 3, 5, 7], f"two-squares.edge: markers {edges}")
    if failures:
        print(f"{len(failures)} failures")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
