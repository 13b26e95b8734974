#!/usr/bin/env python3
"""Writes the seed corpora of the fuzz targets into tests/fuzz/corpus/<target>/.

Seeds: small closed parts (hand-made, and the smallest shared parts whole), the shared
parts and bad meshes cut down to their first faces (open meshes: the readers and the
first checks of validation), every part in every format the target reads, and
hand-written hostile cases: NaN, inf, 1e308, subnormal and out-of-range coordinates,
huge declared counts, repeated and out-of-range indices, zero-area and collinear faces.

Run from anywhere; it rewrites the corpus directories from scratch:
    python3 tests/fuzz/make_seeds.py [--shared ../shared]
"""
import argparse
import json
import math
import os
import shutil
import struct

HERE = os.path.dirname(os.path.abspath(__file__))


# ----------------------------------------------------------------- meshes
def cube(s=1.0, o=(0.0, 0.0, 0.0)):
    pts = [(o[0] + s * (i & 1), o[1] + s * ((i >> 1) & 1), o[2] + s * ((i >> 2) & 1)) for i in range(8)]
    quads = [(0, 2, 3, 1), (4, 5, 7, 6), (0, 1, 5, 4), (2, 6, 7, 3), (0, 4, 6, 2), (1, 3, 7, 5)]
    return pts, [list(q) for q in quads]


def tetra():
    return [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)], [[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]]


def notched_block():
    """An L-shaped prism (a step): one concave region, 8 faces."""
    prof = [(0, 0), (3, 0), (3, 1), (1, 1), (1, 2), (0, 2)]  # counter-clockwise in x, z
    n = len(prof)
    pts = [(x, 0.0, z) for x, z in prof] + [(x, 2.0, z) for x, z in prof]
    # The profile is counter-clockwise in (x, z), which makes y = 0 face -y.
    faces = [[i for i in range(n)], [n + i for i in reversed(range(n))]]
    for i in range(n):
        j = (i + 1) % n
        faces.append([i, n + i, n + j, j])
    return pts, faces


def triangulate(faces):
    out = []
    for f in faces:
        for k in range(1, len(f) - 1):
            out.append([f[0], f[k], f[k + 1]])
    return out


def read_binary_stl(path):
    data = open(path, 'rb').read()
    n = struct.unpack_from('<I', data, 80)[0]
    if 84 + 50 * n != len(data):
        return read_ascii_stl(data.decode('latin1'))
    pts, faces, index = [], [], {}
    for i in range(n):
        vals = struct.unpack_from('<12f', data, 84 + 50 * i)
        f = []
        for k in range(3):
            p = vals[3 + 3 * k: 6 + 3 * k]
            if p not in index:
                index[p] = len(pts)
                pts.append(p)
            f.append(index[p])
        faces.append(f)
    return pts, faces


def read_ascii_stl(text):
    pts, faces, index, f = [], [], {}, []
    for line in text.splitlines():
        t = line.split()
        if t and t[0] == 'vertex':
            p = tuple(float(x) for x in t[1:4])
            if p not in index:
                index[p] = len(pts)
                pts.append(p)
            f.append(index[p])
        elif t and t[0] == 'endfacet':
            faces.append(f)
            f = []
    return pts, faces


def read_off(path):
    lines = [l.split('#')[0].split() for l in open(path)]
    lines = [l for l in lines if l]
    nv, nf = int(lines[1][0]), int(lines[1][1])
    pts = [tuple(float(x) for x in l[:3]) for l in lines[2:2 + nv]]
    faces = [[int(x) for x in l[1:1 + int(l[0])]] for l in lines[2 + nv:2 + nv + nf]]
    return pts, faces


def read_part(path):
    return read_off(path) if path.lower().endswith('.off') else read_binary_stl(path)


def cut(mesh, k):
    """The first k faces, their vertices renumbered in order of use."""
    pts, faces = mesh
    remap, out_pts, out_faces = {}, [], []
    for f in faces[:k]:
        g = []
        for v in f:
            if v not in remap:
                remap[v] = len(out_pts)
                out_pts.append(pts[v])
            g.append(remap[v])
        out_faces.append(g)
    return out_pts, out_faces


# ----------------------------------------------------------------- writers
def num(x):
    return repr(float(x)) if isinstance(x, float) else str(x)


def off(mesh):
    pts, faces = mesh
    s = 'OFF\n%d %d 0\n' % (len(pts), len(faces))
    s += ''.join('%s %s %s\n' % tuple(num(c) for c in p) for p in pts)
    s += ''.join('%d %s\n' % (len(f), ' '.join(map(str, f))) for f in faces)
    return s.encode()


def obj(mesh, groups=True):
    pts, faces = mesh
    s = ''.join('v %s %s %s\n' % tuple(num(c) for c in p) for p in pts)
    half = len(faces) // 2
    for i, f in enumerate(faces):
        if groups and i == 0:
            s += 'g first\n'
        if groups and i == half:
            s += 'g second default\n'
        s += 'f ' + ' '.join('%d/%d' % (v + 1, v + 1) if i % 3 == 1 else
                             ('%d' % (v - len(pts)) if i % 3 == 2 else '%d' % (v + 1)) for v in f) + '\n'
    return s.encode()


def stl_ascii(mesh):
    pts, faces = mesh
    s = 'solid part\n'
    for f in triangulate(faces):
        s += ' facet normal 0 0 0\n  outer loop\n'
        s += ''.join('   vertex %s %s %s\n' % tuple(num(c) for c in pts[v]) for v in f)
        s += '  endloop\n endfacet\n'
    return (s + 'endsolid part\n').encode()


def f32(x):
    """x as float32 would round it: beyond the float range, an infinity."""
    return math.copysign(math.inf, x) if math.isfinite(x) and abs(x) > 3.4028235677973366e38 else x


def facets(mesh):
    """The harness input of fuzz_analysis_stl: 36 bytes (3 x 3 float32) a triangle."""
    pts, faces = mesh
    return b''.join(struct.pack('<9f', *[f32(c) for v in f for c in pts[v]]) for f in triangulate(faces))


def stl_binary(mesh, header=b'binary'):
    tris = triangulate(mesh[1])
    body = b''.join(b'\0' * 12 + facets((mesh[0], [f])) + b'\0\0' for f in tris)
    return header.ljust(80, b' ') + struct.pack('<I', len(tris)) + body


def ply(mesh, fmt='ascii', vtype='double', itype='int'):
    pts, faces = mesh
    head = 'ply\nformat %s 1.0\ncomment seed\nelement vertex %d\n' % (fmt, len(pts))
    head += ''.join('property %s %s\n' % (vtype, c) for c in 'xyz')
    head += 'element face %d\nproperty list uchar %s vertex_indices\nend_header\n' % (len(faces), itype)
    if fmt == 'ascii':
        body = ''.join('%s %s %s\n' % tuple(num(c) for c in p) for p in pts)
        body += ''.join('%d %s\n' % (len(f), ' '.join(map(str, f))) for f in faces)
        return (head + body).encode()
    e = '<' if fmt == 'binary_little_endian' else '>'
    vc = {'double': 'd', 'float': 'f'}[vtype]
    ic = {'int': 'i', 'uint': 'I', 'ushort': 'H'}[itype]
    body = b''.join(struct.pack(e + 3 * vc, *(map(f32, p) if vc == 'f' else p)) for p in pts)
    body += b''.join(struct.pack(e + 'B' + len(f) * ic, len(f), *f) for f in faces)
    return head.encode() + body


# ----------------------------------------------------------------- hostile
def hostile_meshes():
    """Closed tiny parts with absurd geometry, and broken lists."""
    pts, faces = cube()
    out = {}
    for name, value in [('nan', float('nan')), ('inf', float('inf')), ('minus_inf', float('-inf')),
                        ('1e308', 1e308), ('minus_1e308', -1e308), ('subnormal', 5e-324),
                        ('tiny', 1e-300), ('float_max', 3.4028234663852886e38)]:
        p = list(pts)
        p[7] = (p[7][0], p[7][1], value)
        out['cube_vertex_' + name] = (p, faces)
    out['cube_scaled_1e300'] = cube(1e300)
    out['cube_scaled_1e-300'] = cube(1e-300)
    out['cube_scaled_subnormal'] = cube(5e-324 * 8)
    out['cube_scaled_1e150'] = cube(1e150)
    out['cube_far_1e300'] = cube(1.0, (1e300, 0.0, 0.0))
    out['cube_mixed_1e-300_1e12'] = ([(1e-300 if i & 1 == 0 else 0.1, 1e-12 if i & 2 == 0 else 1.000000000001,
                                       0.0 if i & 4 == 0 else 1e12) for i in range(8)], faces)
    t = tetra()
    out['tetra_collinear'] = ([(0, 0, 0), (1, 0, 0), (2, 0, 0), (0, 0, 1)], t[1])
    out['tetra_flat'] = ([(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)], t[1])
    out['tetra_repeated_index'] = (t[0], [[0, 0, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]])
    out['tetra_inverted'] = (t[0], [list(reversed(f)) for f in t[1]])
    out['tetra_duplicate_face'] = (t[0], t[1] + [t[1][0]])
    out['two_tetra_touching'] = (t[0] + [(1, 1, 1)], t[1] + [[1, 2, 4], [1, 4, 3], [2, 3, 4], [1, 3, 2]])
    out['degenerate_face_two_vertices'] = (t[0], t[1] + [[0, 1]])
    out['empty_face'] = (t[0], t[1] + [[]])
    return out


def hostile_text():
    """Per format, texts that the mesh writers above cannot produce."""
    return {
        'off': {
            'huge_counts': b'OFF\n4294967295 4294967295 0\n0 0 0\n3 0 0 0\n',
            'huger_counts': b'OFF\n18446744073709551615 18446744073709551615 0\n',
            'negative_counts': b'OFF\n-1 -1 0\n',
            'face_huge_arity': b'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4294967295 0 1 2\n',
            'index_out_of_range': b'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n',
            'index_huge': b'OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 4294967295\n',
            'coordinate_overflow': b'OFF\n3 1 0\n1e999 0 0\n1 0 0\n0 1 0\n3 0 1 2\n',
            'coordinate_nan_text': b'OFF\n3 1 0\nnan 0 0\n1 0 0\n0 1 0\n3 0 1 2\n',
            'coordinate_inf_text': b'OFF\n3 1 0\ninf -infinity 0\n1 0 0\n0 1 0\n3 0 1 2\n',
            'coordinate_hex': b'OFF\n3 1 0\n0x1p-1074 0 0\n1 0 0\n0 1 0\n3 0 1 2\n',
            'header_variants': b'COFF\n3 1 0\n0 0 0 1 1 1 1\n1 0 0 1 1 1 1\n0 1 0 1 1 1 1\n3 0 1 2 255 0 0\n',
            'header_counts_same_line': b'OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n',
            'crlf_comments': b'OFF\r\n# c\r\n3 1 0 # counts\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n',
            'truncated': b'OFF\n8 6 0\n0 0 0\n1 0',
            'binary': b'OFF BINARY\n',
            'four_d': b'4OFF\n',
        },
        'obj': {
            'negative_index': b'v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n',
            'zero_index': b'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n',
            'index_out_of_range': b'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\nf -9 1 2\n',
            'index_overflow': b'v 0 0 0\nf 1 1 99999999999999999999999\nf -9223372036854775808 1 1\n',
            'slashes': b'v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 2//1 3/1\n',
            'groups_and_junk': b'o thing\ng a b default\nusemtl x\ns off\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\ng\nf 3 2 1\n',
            'nan_coordinates': b'v nan 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n',
            'face_before_vertices': b'f 1 2 3\nv 0 0 0\n',
            'empty_face': b'v 0 0 0\nf\n',
        },
        'stl': {
            'ascii_vertex_outside_facet': b'solid x\nvertex 0 0 0\nendsolid\n',
            'ascii_unterminated': b'solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n',
            'ascii_endfacet_alone': b'solid x\nendfacet\n',
            'ascii_four_vertices': b'solid x\nfacet normal 0 0 1\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nvertex 1 1 0\nendfacet\nendsolid\n',
            'ascii_nan': b'solid x\nfacet normal 0 0 1\nvertex nan 0 0\nvertex 1 0 0\nvertex 0 1 0\nendfacet\nendsolid\n',
            'binary_count_too_big': b'\0' * 80 + struct.pack('<I', 0xffffffff) + b'\0' * 50,
            'binary_count_zero': b'\0' * 80 + struct.pack('<I', 0),
            'binary_nan': stl_binary(([(float('nan'), 0, 0), (1, 0, 0), (0, 1, 0)], [[0, 1, 2]])),
            'binary_solid_header': stl_binary(tetra(), header=b'solid but binary'),
            'short': b'solid',
        },
        'ply': {
            'huge_count': b'ply\nformat ascii 1.0\nelement vertex 4294967295\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n',
            'huge_list': b'ply\nformat binary_little_endian 1.0\nelement face 1\nproperty list uint uint vertex_indices\nend_header\n\xff\xff\xff\xff\0\0\0\0',
            'list_length_float': b'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n'
                                 b'element face 1\nproperty list float int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n2.5 0 1 2\n',
            'negative_index': b'ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n'
                              b'element face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n',
            'extra_elements': b'ply\nformat ascii 1.0\nelement material 2\nproperty uchar r\nelement vertex 3\nproperty float x\n'
                              b'property float y\nproperty float z\nproperty uchar red\nelement face 1\nproperty list uchar int vertex_index\n'
                              b'element edge 0\nproperty int a\nend_header\n1\n2\n0 0 0 9\n1 0 0 9\n0 1 0 9\n3 0 1 2\n',
            'no_format': b'ply\nelement vertex 0\nend_header\n',
            'unknown_type': b'ply\nformat ascii 1.0\nelement vertex 1\nproperty int128 x\nend_header\n',
            'big_endian_nan': ply(([(float('nan'), 0.0, 0.0), (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)], [[0, 1, 2]]),
                                  'binary_big_endian'),
            'crlf': b'ply\r\nformat ascii 1.0\r\nelement vertex 3\r\nproperty double x\r\nproperty double y\r\nproperty double z\r\n'
                    b'element face 1\r\nproperty list uchar int vertex_indices\r\nend_header\r\n0 0 0\r\n1 0 0\r\n0 1 0\r\n3 0 1 2\r\n',
        },
    }


GROUP_SEEDS = {
    'one': {'top': [1]},
    'two': {'a': [0, 2], 'b': [1, 3, 5]},
    'all': {'walls': [0, 1, 2, 3], 'caps': [4, 5]},
    'empty_object': {},
    'empty_group': {'a': []},
    'duplicate_face': {'a': [1, 1]},
    'face_in_two': {'a': [1], 'b': [1]},
    'out_of_range': {'a': [6]},
    'huge_index': {'a': [4294967296]},
    'fraction': {'a': [0.5]},
    'negative': {'a': [-1]},
    'negative_zero': {'a': [-0.0]},
    'not_a_list': {'a': 3},
    'nested': {'a': [[1]]},
    'string_entry': {'a': ['1']},
    'unicode_name': {'\u00e9t\u00e9 \u2603 </script>': [2]},
    'empty_name': {'': [3]},
}
GROUP_TEXT = {
    'array': b'[1, 2]',
    'exponent': b'{"a": [1e0, 2E+0, 3e-0]}',
    'big_exponent': b'{"a": [1e400]}',
    'nan_literal': b'{"a": [NaN]}',
    'trailing_garbage': b'{"a": [1]} x',
    'duplicate_key': b'{"a": [1], "a": [2]}',
    'escapes': b'{"\\u0000\\ud83d\\ude00\\n": [1]}',
    'lone_surrogate': b'{"\\ud800": [1]}',
    'deep': b'{"a": ' + b'[' * 200 + b']' * 200 + b'}',
    'deep_objects': b'{"a": ' + b'{"b": ' * 120 + b'1' + b'}' * 120 + b'}',
    'whitespace': b' \t\r\n{ "a" : [ 0 , 1 ] } \n',
    'unterminated': b'{"a": [1, 2',
    'empty': b'',
    'null': b'null',
}


# ----------------------------------------------------------------- main
def main():
    ap = argparse.ArgumentParser()
    ap.add_argument('--shared', default=os.path.join(HERE, '..', '..', '..', 'shared'))
    args = ap.parse_args()
    parts = os.path.join(args.shared, 'data', 'parts')
    bad = os.path.join(args.shared, 'data', 'bad')

    corpus = os.path.join(HERE, 'corpus')
    shutil.rmtree(corpus, ignore_errors=True)

    def put(target, name, data):
        d = os.path.join(corpus, target)
        os.makedirs(d, exist_ok=True)
        with open(os.path.join(d, name), 'wb') as f:
            f.write(data)

    # Closed tiny parts, whole.
    closed = {'cube': cube(), 'tetra': tetra(), 'notched_block': notched_block()}
    for name in ['trimesh_7_8ths_cube.stl', 'prusa_plug-aligner.stl']:
        closed[name.split('.')[0]] = read_part(os.path.join(parts, name))
    closed['bad_trimesh_shared'] = read_part(os.path.join(bad, 'trimesh_shared.STL'))
    # Cut down: the first faces of larger parts and of bad meshes (open meshes).
    cuts = {}
    for name, k in [('occt_brep_mal_tige.off', 40), ('trimesh_plate_holes.STL', 30),
                    ('trimesh_featuretype_from_step.off', 24), ('occt_shape.stl', 20)]:
        cuts['cut_' + name.split('.')[0]] = cut(read_part(os.path.join(parts, name)), k)
    for name, k in [('prusa_endstop-block_FLIPPED.off', 40), ('trimesh_multibody.stl', 40),
                    ('trimesh_angle_block.STL', 30), ('occt_propeller.stl', 30)]:
        cuts['bad_cut_' + name.split('.')[0]] = cut(read_part(os.path.join(bad, name)), k)
    hostile = hostile_meshes()
    meshes = {**closed, **cuts, **hostile}

    for name, m in meshes.items():
        put('fuzz_mesh_reader_off', name + '.off', off(m))
        put('fuzz_mesh_reader_obj', name + '.obj', obj(m))
        if all(len(f) >= 3 for f in m[1]):
            put('fuzz_mesh_reader_stl', name + '.ascii.stl', stl_ascii(m))
            put('fuzz_mesh_reader_stl', name + '.binary.stl', stl_binary(m))
        put('fuzz_mesh_reader_ply', name + '.ascii.ply', ply(m))
        put('fuzz_mesh_reader_ply', name + '.le.ply', ply(m, 'binary_little_endian', 'float', 'uint'))
        put('fuzz_mesh_reader_ply', name + '.be.ply', ply(m, 'binary_big_endian', 'double', 'int'))
    for fmt, cases in hostile_text().items():
        for name, data in cases.items():
            put('fuzz_mesh_reader_' + fmt, name + '.' + fmt, data)

    # The pipeline: closed parts and hostile geometry only (cut-down parts fail at once).
    for name, m in {**closed, **hostile}.items():
        if len(triangulate(m[1])) > 48:
            continue
        put('fuzz_analysis_off', name + '.off', off(m))
        if all(len(f) >= 3 for f in m[1]):
            put('fuzz_analysis_stl', name + '.facets', facets(m))

    for name, g in GROUP_SEEDS.items():
        put('fuzz_groups', name + '.json', json.dumps(g).encode())
    for name, data in GROUP_TEXT.items():
        if data:
            put('fuzz_groups', name + '.json', data)

    # STEP: the smallest shared parts whole, and cut down to their first entities (the
    # parser and the checks of an incomplete file).
    step = os.path.join(args.shared, 'data', 'step')
    for name in ['bug25169_box-openshell.stp', 'bug3883_xr2-ct-214_l-bracket.stp', 'bug3883_xr2-ct-214_plate.stp']:
        with open(os.path.join(step, name), 'rb') as f:
            data = f.read()
        put('fuzz_step', name, data)
        lines = data.split(b'\n')
        data_at = next(i for i, l in enumerate(lines) if l.strip() == b'DATA;')
        for keep in (40, 200):
            cut_step = b'\n'.join(lines[:data_at + 1 + keep] + [b'ENDSEC;', b'END-ISO-10303-21;', b''])
            put('fuzz_step', 'cut%d_%s' % (keep, name), cut_step)

    for target in sorted(os.listdir(corpus)):
        files = os.listdir(os.path.join(corpus, target))
        size = sum(os.path.getsize(os.path.join(corpus, target, f)) for f in files)
        print('%-24s %4d seeds %8d bytes' % (target, len(files), size))


if __name__ == '__main__':
    main()
