#!/usr/bin/env python3
"""Writes the seed corpora of the fuzz targets (fuzz/corpus/<target>/).

Run from anywhere: python3 fuzz/make_seed_corpus.py. Each target's byte layout
is documented at the top of its check (fuzz/<target>_check.cpp) and, for the
point sets shared by hull2 / certify / kernels / rt2, in fuzz/fuzz_input.hpp.
The script only (over)writes its own seed files: crash reproducers copied into
a corpus directory stay there and are replayed by ctest (fuzz_<target>_replay).

predicates: spec indices 0 orient2d, 1 orient3d, 2 power2d, 3 power3d,
4..8 orient_d(2..6), 9..12 power_d(2..5); encodings 0 raw binary64, 1 int8,
2 int8 scaled by 2^(8s | 4s), 3 table. Mostly degenerate configurations:
collinear, coplanar, cocircular, cospherical, lifted points on a plane,
duplicates, all points equal.
read_points / read_indices: valid files of every format and one file per
error the readers report.
hull2 / certify / kernels / rt2 / hull3 / rtd / rt3: small degenerate point sets
(collinear, cocircular, cospherical, duplicates, ulp jitter, huge / tiny /
subnormal magnitudes; rtd also in R^4 and R^5, with target weights for the
instant flip) in the point-set layout of fuzz_input.hpp.
"""
import math
import os
import struct

CORPUS = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")


# ---- predicates (fuzz/predicates_check.cpp) -----------------------------------
def header(spec, encoding, ids, raw_ids=False, scale=0):
    flags = encoding | (4 if raw_ids else 0)
    return bytes([spec, flags, scale & 0xFF]) + bytes(ids)


def f64(values):
    return b"".join(struct.pack("<d", v) for v in values)


def i8(values):
    return b"".join(struct.pack("<b", v) for v in values)


def flat(points):
    return [c for p in points for c in p]


def next_up(x):
    return math.nextafter(x, math.inf)


PREDICATES = {
    # orient2d: collinear (raw doubles), near-collinear decimals, identical points
    "orient2d_collinear": header(0, 0, [0, 1, 2]) + f64(flat([(0, 0), (1, 1), (2, 2)])),
    "orient2d_decimals": header(0, 0, [2, 0, 1]) + f64(flat([(0.1, 0.1), (0.2, 0.2), (0.3, 0.3)])),
    "orient2d_one_ulp": header(0, 0, [0, 1, 2]) + f64(flat([(1, 1), (2, 2), (3, next_up(3.0))])),
    "orient2d_identical": header(0, 1, [5, 3, 9]) + i8(flat([(7, -3)] * 3)),
    "orient2d_repeated_id": header(0, 1, [4, 4, 7], raw_ids=True) + i8(flat([(1, 2), (1, 2), (3, 3)])),
    # orient3d: coplanar square
    "orient3d_coplanar": header(1, 1, [0, 1, 2, 3]) + i8(flat([(0, 0, 0), (1, 0, 0), (0, 1, 0), (1, 1, 0)])),
    # power2d: lattice points on x^2 + y^2 = 25; lifted points on a plane
    "power2d_cocircular": header(2, 1, [3, 1, 0, 2]) + i8(flat([(3, 4), (-3, 4), (5, 0), (0, -5)]) + [0, 0, 0, 0]),
    "power2d_lifted_plane": header(2, 1, [0, 1, 2, 3])
    + i8(flat([(0, 0), (2, 1), (-1, 3), (3, -2)]) + [x * x + y * y - x - 2 * y - 3 for x, y in [(0, 0), (2, 1), (-1, 3), (3, -2)]]),
    # power3d: lattice points on x^2 + y^2 + z^2 = 9, plain and scaled to 2^-512 (weights 2^-1024)
    "power3d_cospherical": header(3, 1, [0, 1, 2, 3, 4])
    + i8(flat([(1, 2, 2), (2, 1, 2), (2, 2, 1), (3, 0, 0), (0, 0, -3)]) + [0] * 5),
    "power3d_cospherical_tiny": header(3, 2, [4, 3, 2, 1, 0], scale=-128)
    + i8(flat([(1, 2, 2), (2, 1, 2), (2, 2, 1), (3, 0, 0), (0, 0, -3)]) + [1] * 5),
    # orient_d(6): a short input, every point at the origin
    "orient_d6_all_zero": bytes([8]),
    # orient_d(4): points on a line, scaled to 2^1016
    "orient_d4_line_huge": header(5 + 1, 2, [0, 1, 2, 3, 4], scale=127)
    + i8(flat([(t, 2 * t, -t, 3) for t in (-2, -1, 0, 1, 2)])),
    # orient_d(5): a hyperplane x5 = 0 in raw doubles, one value nudged by an ulp
    "orient_d5_hyperplane_ulp": header(7, 0, [5, 4, 3, 2, 1, 0])
    + f64(flat([(0.5, 0.25, 1, 2, 0), (1, 0, 0, 0, 0), (0, 1, 0, 0, 0), (0, 0, 1, 0, 0), (0, 0, 0, 1, 0), (1, 1, 1, 1, 5e-324)])),
    # power_d(4): lattice points on |x|^2 = 9 in R^4
    "power_d4_cospherical": header(11, 1, [0, 1, 2, 3, 4, 5])
    + i8(flat([(3, 0, 0, 0), (0, 3, 0, 0), (0, 0, 3, 0), (0, 0, 0, 3), (2, 2, 1, 0), (1, 2, 2, 0)]) + [0] * 6),
    # power_d(5): duplicated points with equal weights
    "power_d5_duplicates": header(12, 1, [6, 5, 4, 3, 2, 1, 0])
    + i8(flat([(1, 2, 3, 4, 5)] * 4 + [(0, 0, 0, 0, 0)] * 3) + [2] * 7),
    # extreme magnitudes from the table (encoding 3)
    "orient3d_extreme": header(1, 3, [0, 1, 2, 3]) + bytes([1, 11, 27, 10, 4, 2, 0, 17, 11, 12, 26, 6]),
    "power_d3_extreme": header(10, 3, [1, 0, 3, 2, 4]) + bytes([11, 1, 10, 27, 4, 2, 3, 19, 0, 6, 7, 8, 9, 10, 11, 0, 0, 1, 1, 11]),
}


# ---- point sets (fuzz/fuzz_input.hpp) -----------------------------------------
# A point set: [n - 1, scale] + per point [mode, operands..., (weight byte)].
# The helpers below return one point's bytes without its weight.
def small(*p):  # mode 0: integers in [-8, 7]
    assert all(-8 <= c <= 7 for c in p)
    return bytes([0] + [(c + 8) & 15 for c in p])


def int8(*p):  # mode 1
    return bytes([1]) + struct.pack("<%db" % len(p), *p)


def copy(k):  # mode 2: a copy of point k (k < this point's index)
    return bytes([2, k])


def jitter(k, *steps):  # mode 3: point k moved by steps[c] ulps per coordinate
    return bytes([3, k] + [s + 2 for s in steps])


def on_line(a, b, t):  # mode 4: a + t (b - a), t a multiple of 1/4
    return bytes([4, a, b]) + struct.pack("<b", int(round(t * 4)))


def raw(*p):  # mode 5: binary64 values
    return bytes([5]) + f64(p)


def special(*codes):  # mode 6: table codes (fuzz_input.cpp special_value)
    return bytes([6] + list(codes))


def lattice(k):  # mode 7: integer point k on x²+y² = 25 / x²+y²+z² = 9
    return bytes([7, k])


def scale_byte(e):  # coordinates times 2^e, e a multiple of 16 in [-1024, 1008]
    if e == 0:
        return 0
    assert e % 16 == 0
    return (((e // 16) << 1) | 1) & 0xFF


def point_set(points, weights=None, e=0):
    out = bytes([len(points) - 1, scale_byte(e)])
    for i, p in enumerate(points):
        out += p
        if weights is not None:
            out += struct.pack("<b", int(round(weights[i] * 4)))
    return out


SQUARE_WITH_EDGE_POINTS = [small(0, 0), small(4, 0), small(4, 4), small(0, 4), small(2, 0), small(4, 2),
                           small(2, 4), small(0, 2), small(2, 2), copy(1)]
COLLINEAR2 = [small(-3, -3), small(0, 0), small(5, 5), on_line(0, 2, 0.25), on_line(1, 2, -1.5)]
CIRCLE12 = [lattice(k) for k in range(12)]
GRID = [small(x, y) for x in range(-2, 2) for y in range(-2, 2)]
JITTER = [small(0, 0), small(1, 1), small(2, 2), jitter(1, 1, 0), jitter(1, 0, -1), jitter(2, -2, 2), small(0, 3)]
DUPLICATES = [small(1, 1), copy(0), small(-3, 2), copy(2), copy(0), small(5, -4), copy(5), small(0, 0)]
DECIMALS = [raw(0.1, 0.1), raw(0.2, 0.2), raw(0.3, 0.3), raw(0.1, 0.3), raw(0.3, 0.1), raw(0.2, 0.20000000000000004)]
# table codes: 0 zero, 1 2^-1074, 2 1e-310, 3 DBL_MIN, 6 one, 10 1e300, 11 DBL_MAX/8; bit 4 negative
EXTREMES = [special(1, 1), special(17, 1), special(1, 17), special(10, 0), special(0, 26), special(11, 11), special(27, 2)]
MIXED_MAGNITUDES = [special(6, 0), special(0, 6), special(22, 0), special(0, 22), special(3, 3), special(2, 0)]
FLAT_FAN = [small(-8, -8), small(5, 0), small(-8, 7), small(-8, 1), small(-8, -1)]
SPHERE30 = [lattice(k) for k in range(30)]
CUBE = [small(x, y, z) for x in (0, 3) for y in (0, 3) for z in (0, 3)]
COPLANAR_PLUS_ONE = [small(0, 0, 0), small(4, 0, 0), small(0, 4, 0), small(4, 4, 0), small(2, 2, 0), small(1, 3, 0),
                     small(2, 2, 5)]
CUBE_FACE_CENTRES = CUBE + [small(0, 1, 1), small(3, 1, 1), small(1, 0, 2), small(1, 1, 0), copy(3)]
GRID3 = [small(x, y, z) for x in range(3) for y in range(3) for z in range(2)]
JITTER3 = [small(0, 0, 0), small(2, 0, 0), small(0, 2, 0), small(0, 0, 2), jitter(1, 1, 0, 0), jitter(2, 0, -1, 1),
           small(2, 2, 2), jitter(6, 0, 0, -1)]

# ---- read_points (fuzz/read_points_check.cpp) ----------------------------------
# mode byte: bits 0-1 extension (0 xyz, 1 off, 2 ply, 3 odd-case), bit 2 3D, bit 3 weighted
XYZ2, XYZ3, XYZ2W, XYZ3W = 0, 4, 8, 12
OFF3, OFF2 = 1 | 4, 1
PLY3, PLY3W, PLY2 = 2 | 4, 2 | 4 | 8, 2
ODD_XYZ, ODD_OFF = 3, 3 | 4 | 16


def ply_binary(points, weights=None, kind="double", endian="little"):
    fmt = {"double": "d", "float": "f"}[kind]
    e = "<" if endian == "little" else ">"
    props = "".join("property %s %s\n" % (kind, c) for c in "xyz")
    if weights is not None:
        props += "property %s w\n" % kind
    head = ("ply\nformat binary_%s_endian 1.0\nelement vertex %d\n%send_header\n" % (endian, len(points), props)).encode()
    body = b""
    for i, p in enumerate(points):
        vals = list(p) + ([weights[i]] if weights is not None else [])
        body += struct.pack(e + fmt * len(vals), *vals)
    return head + body


TETRA = [(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)]
READ_POINTS = {
    "xyz2_square": bytes([XYZ2]) + b"0 0\n1 0\n1 1\n0 1\n",
    "xyz2_comments_blank_crlf": bytes([XYZ2]) + b"# a square\r\n0 0\r\n\r\n1 0 # corner\r\n1 1\r\n  0   1  \r\n",
    "xyz3_extremes": bytes([XYZ3]) + b"1e308 -1e308 0\n4.9e-324 -0 2.2250738585072014e-308\n1 2 3\n.5 -.5e1 +7\n",
    "xyz3_hexfloat": bytes([XYZ3]) + b"0x1p3 1 1\n1 2 3\n0 0 0\n1 1 1\n",
    "xyz2w_weights": bytes([XYZ2W]) + b"0 0 0.5\n1 0 -1\n0 1 0\n1 1 1e-300\n",
    "xyz3w_tetra": bytes([XYZ3W]) + b"0 0 0 1\n1 0 0 1\n0 1 0 1\n0 0 1 1\n",
    "xyz2_nan": bytes([XYZ2]) + b"0 0\nnan 1\n1 1\n",
    "xyz2_inf": bytes([XYZ2]) + b"0 0\n1 -inf\n1 1\n",
    "xyz2_overflow": bytes([XYZ2]) + b"0 0\n1e999 1\n1 1\n",
    "xyz2_malformed": bytes([XYZ2]) + b"0 0\n1 1.2.3\n1 1\n",
    "xyz2_wrong_columns": bytes([XYZ2]) + b"0 0\n1 1 1\n1 1\n",
    "xyz3_too_few": bytes([XYZ3]) + b"0 0 0\n1 1 1\n2 2 2\n",
    "xyz2_empty": bytes([XYZ2]),
    "xyz2_binary_garbage": bytes([XYZ2]) + bytes(range(256)),
    "xyz2_long_line": bytes([XYZ2]) + b"1 " * 40000 + b"\n0 0\n",
    "odd_case_xyz": bytes([ODD_XYZ]) + b"0 0\n1 0\n0 1\n",
    "off3_tetra": bytes([OFF3]) + b"OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n",
    "off3_comments": bytes([OFF3]) + b"OFF\n# comment\n4 0 0\n\n0 0 0\n1 0 0 # x\n0 1 0\n0 0 1\n",
    "off2_flat": bytes([OFF2]) + b"OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n",
    "off2_not_flat": bytes([OFF2]) + b"OFF\n3 0 0\n0 0 0\n1 0 1\n0 1 0\n",
    "off3_short": bytes([OFF3]) + b"OFF\n4 0 0\n0 0 0\n1 0 0\n",
    "off3_bad_keyword": bytes([OFF3]) + b"COFF\n4 0 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n",
    "off3_nan": bytes([OFF3]) + b"OFF\n4 0 0\n0 0 0\nnan 0 0\n0 1 0\n0 0 1\n",
    "odd_case_off": bytes([ODD_OFF]) + b"OFF\n4 0 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n",
    "ply3_ascii": bytes([PLY3]) + b"ply\nformat ascii 1.0\ncomment tetra\nelement vertex 4\nproperty float x\n"
    b"property float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
    b"0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n",
    "ply3w_ascii": bytes([PLY3W]) + b"ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
    b"property double z\nproperty double weight\nend_header\n0 0 0 1\n1 0 0 2\n0 1 0 3\n0 0 1 4\n",
    "ply2_ascii": bytes([PLY2]) + b"ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty double y\n"
    b"property double z\nend_header\n0 0 0\n1 0 0\n0 1 0\n",
    "ply3_binary_le": bytes([PLY3]) + ply_binary(TETRA),
    "ply3w_binary_be_float": bytes([PLY3W]) + ply_binary(TETRA, [1, 2, 3, 4], "float", "big"),
    "ply3_binary_truncated": bytes([PLY3]) + ply_binary(TETRA)[:-5],
    "ply3_binary_nan": bytes([PLY3]) + ply_binary(TETRA[:3] + [(math.nan, 0, 1)]),
    "ply3_missing_z": bytes([PLY3]) + b"ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\n"
    b"end_header\n0 0\n1 0\n0 1\n1 1\n",
    "ply3_huge_count": bytes([PLY3]) + b"ply\nformat binary_little_endian 1.0\nelement vertex 4000000000\n"
    b"property double x\nproperty double y\nproperty double z\nend_header\n" + bytes(48),
    "ply_not_ply": bytes([PLY3]) + b"plx\nformat ascii 1.0\n",
}

# ---- read_indices (fuzz/read_indices_check.cpp) ---------------------------------
# mode byte: bit 0 set → triangles, clear → a cycle
CYCLE, TRIS = 0, 1
READ_INDICES = {
    "cycle": bytes([CYCLE]) + b"0\n3\n1\n",
    "cycle_comments_crlf": bytes([CYCLE]) + b"# hull\r\n0\r\n\r\n2 # x\r\n1\r\n",
    "cycle_negative": bytes([CYCLE]) + b"0\n-1\n2\n",
    "cycle_too_large": bytes([CYCLE]) + b"0\n4294967296\n2\n",
    "cycle_largest": bytes([CYCLE]) + b"0\n4294967295\n2\n",
    "cycle_two_per_line": bytes([CYCLE]) + b"0 1\n2\n",
    "cycle_float": bytes([CYCLE]) + b"0\n1.0\n2\n",
    "cycle_empty": bytes([CYCLE]),
    "triangles": bytes([TRIS]) + b"0 1 2\n0 2 3\n0 3 1\n1 3 2\n",
    "triangles_qhull": bytes([TRIS]) + b"4\n0 1 2\n0 2 3\n0 3 1\n1 3 2\n",
    "triangles_qhull_count_mismatch": bytes([TRIS]) + b"3\n0 1 2\n0 2 3\n",
    "triangles_qhull_nonsimplicial": bytes([TRIS]) + b"1\n0 1 2 3\n",
    "triangles_two_tokens": bytes([TRIS]) + b"0 1 2\n0 1\n",
    "triangles_garbage": bytes([TRIS]) + bytes(range(1, 128)),
    "triangles_plus_sign": bytes([TRIS]) + b"+0 1 2\n",
}

# ---- hull2 (fuzz/hull2_check.cpp): a point set, then edit bytes -------------------
HULL2 = {
    "square_edge_points": point_set(SQUARE_WITH_EDGE_POINTS) + bytes([3, 5]),
    "collinear": point_set(COLLINEAR2),
    "circle_lattice": point_set(CIRCLE12) + bytes([7, 0]),
    "grid4x4": point_set(GRID) + bytes([2, 9]),
    "ulp_jitter": point_set(JITTER) + bytes([1, 1]),
    "duplicates": point_set(DUPLICATES) + bytes([0, 4]),
    "decimals": point_set(DECIMALS),
    "extremes": point_set(EXTREMES),
    "mixed_magnitudes": point_set(MIXED_MAGNITUDES),
    "huge_grid": point_set(GRID, e=992),
    "tiny_grid": point_set(GRID, e=-1024),
    "three_points": point_set([small(0, 0), small(1, 0), small(0, 1)]),
    "one_point": point_set([small(0, 0)]),
    "all_equal": point_set([small(3, 3), copy(0), copy(0), copy(1)]),
    # Regression (found by fuzz_hull2): certify::hull2 at Level::exact accepted
    # the cycle [0 1 3 4], which leaves point 2 = (-8, 7) strictly outside edge
    # (1, 3): the fan sector search from vertex 0 picked the flat sector
    # (0, 3, 4) along the collinear edge x = -8. Edit byte 2 removes vertex 2.
    "regression_exact_flat_fan_sector": point_set(FLAT_FAN) + bytes([2]),
}

# ---- certify (fuzz/certify_check.cpp) ---------------------------------------------
# flags: bits 0-1 kind (0 hull2, 1 hull3, 2 rt2), bit 2 weighted, bit 3 edit the answer
HULL2_K, HULL3_K, RT2_K, WEIGHTED, EDIT = 0, 1, 2, 4, 8


def edits(*ops):  # (op, operand bytes...) per edit; op 0 remove, 1 duplicate,
    out = bytes([len(ops)])  # 2 replace, 3 swap, 4 flip/reverse, 5 rotate, 6 insert
    for op in ops:
        out += bytes(op)
    return out


CERTIFY = {
    "hull2_answer": bytes([HULL2_K | EDIT]) + point_set(SQUARE_WITH_EDGE_POINTS) + edits(),
    "hull2_remove": bytes([HULL2_K | EDIT]) + point_set(SQUARE_WITH_EDGE_POINTS) + edits((0, 2)),
    "hull2_rotate": bytes([HULL2_K | EDIT]) + point_set(CIRCLE12) + edits((5, 0)),
    "hull2_insert": bytes([HULL2_K | EDIT]) + point_set(GRID) + edits((6, 5, 1)),
    "hull2_arbitrary": bytes([HULL2_K]) + point_set(DUPLICATES) + bytes([5, 0, 5, 7, 2, 3]),
    "hull2_collinear": bytes([HULL2_K]) + point_set(COLLINEAR2) + bytes([3, 0, 2, 1]),
    "hull3_answer_cube": bytes([HULL3_K | EDIT]) + point_set(CUBE) + edits(),
    "hull3_flip_sphere": bytes([HULL3_K | EDIT]) + point_set(SPHERE30[:16]) + edits((4, 3)),
    "hull3_coplanar_plus_one": bytes([HULL3_K | EDIT]) + point_set(COPLANAR_PLUS_ONE) + edits((2, 1, 0, 5)),
    "hull3_face_centres": bytes([HULL3_K | EDIT]) + point_set(CUBE_FACE_CENTRES) + edits((0, 3), (6, 0, 1, 2, 0)),
    "hull3_jitter": bytes([HULL3_K | EDIT]) + point_set(JITTER3) + edits((3, 0, 1)),
    "hull3_arbitrary": bytes([HULL3_K]) + point_set(CUBE) + bytes([4, 0, 1, 2, 0, 2, 3, 0, 3, 1, 1, 3, 2]),
    "hull3_coplanar": bytes([HULL3_K | EDIT]) + point_set(COPLANAR_PLUS_ONE[:6]) + edits(),
    "rt2_answer_circle": bytes([RT2_K | EDIT]) + point_set(CIRCLE12) + edits(),
    "rt2_weighted_grid": bytes([RT2_K | WEIGHTED | EDIT]) + point_set(GRID[:12], [0, 1, -1, 2, 0, 0.25, 3, -2, 1, 0, 0, 5])
    + edits((1, 0, 0)),
    "rt2_swap": bytes([RT2_K | EDIT]) + point_set(SQUARE_WITH_EDGE_POINTS) + edits((3, 0, 1)),
    "rt2_arbitrary": bytes([RT2_K]) + point_set(GRID[:5]) + bytes([2, 0, 1, 2, 1, 3, 2]),
    # Regression: the same certify::hull2 Level::exact bug as
    # hull2/regression_exact_flat_fan_sector, as an arbitrary output [0 1 3 4].
    "regression_hull2_exact_flat_fan_sector": bytes([HULL2_K]) + point_set(FLAT_FAN) + bytes([4, 0, 1, 3, 4]),
    # Regression (found by fuzz_certify): certify::hull3 rejected the correct
    # hull of a tetrahedron scaled by 2^-608 ("interior-point: all vertices of
    # the surface are coplanar"): squared distances underflow to 0, so the
    # second tetrahedron vertex was the first one again.
    "regression_hull3_tiny_tetrahedron": bytes([HULL3_K | EDIT])
    + point_set([small(0, 0, 0), small(1, 0, 0), small(0, 1, 0), small(0, 0, 1)], e=-608) + edits(),
    "rt2_duplicates": bytes([RT2_K | WEIGHTED | EDIT]) + point_set(DUPLICATES, [0, 0, 1, 1, -1, 0, 2, 0]) + edits((5, 1)),
}

# ---- kernels (fuzz/kernels_check.cpp) ---------------------------------------------
# flags: bit 0 3D, bit 1 ids may be out of range, bit 2 one facet id short
K3, OUT_OF_RANGE, SHORT = 1, 2, 4


def assignment(facets, of_point):
    return bytes([len(facets) - 1] + [v for f in facets for v in f] + list(of_point))


KERNELS = {
    "2d_grid": bytes([0]) + point_set(GRID) + assignment([(0, 1), (5, 10), (3, 12)], [k % 3 for k in range(16)]),
    "2d_collinear": bytes([0]) + point_set(COLLINEAR2) + assignment([(0, 2)], [0] * 5),
    "2d_extremes": bytes([0]) + point_set(EXTREMES) + assignment([(0, 3), (5, 6)], [0, 1, 0, 1, 0, 1, 0]),
    "2d_jitter": bytes([0]) + point_set(JITTER) + assignment([(0, 2), (3, 4)], [0, 1, 0, 1, 0, 1, 0]),
    "2d_repeated_vertex": bytes([0]) + point_set(GRID[:4]) + assignment([(1, 1)], [0] * 4),
    "3d_cube": bytes([K3]) + point_set(CUBE_FACE_CENTRES) + assignment([(0, 1, 2), (0, 4, 1), (7, 6, 5)],
                                                                        [k % 3 for k in range(13)]),
    "3d_coplanar": bytes([K3]) + point_set(COPLANAR_PLUS_ONE) + assignment([(0, 1, 2)], [0] * 7),
    "3d_huge": bytes([K3]) + point_set(GRID3, e=992) + assignment([(0, 1, 2), (3, 4, 5)], [k % 2 for k in range(18)]),
    "3d_tiny": bytes([K3]) + point_set(GRID3, e=-1024) + assignment([(0, 1, 2), (3, 4, 5)], [k % 2 for k in range(18)]),
    "3d_jitter": bytes([K3]) + point_set(JITTER3) + assignment([(0, 1, 2), (1, 2, 3)], [0, 1] * 4),
    "3d_sphere": bytes([K3]) + point_set(SPHERE30) + assignment([(0, 2, 4), (6, 7, 8)], [k % 2 for k in range(30)]),
    "invalid_vertex": bytes([OUT_OF_RANGE]) + point_set(GRID[:4]) + assignment([(0, 5)], [0] * 4),
    "invalid_facet": bytes([K3 | OUT_OF_RANGE]) + point_set(CUBE) + assignment([(0, 1, 2)], [0, 0, 0, 1, 0, 0, 0, 0]),
    "short_ids": bytes([SHORT]) + point_set(GRID[:4]) + assignment([(0, 1)], [0] * 3),
}

# ---- rt2 (fuzz/rt2_check.cpp): flags bit 0 weighted, then a point set ----------------
RT2 = {
    "circle_lattice": bytes([0]) + point_set(CIRCLE12),
    "circle_lattice_weighted": bytes([1]) + point_set(CIRCLE12, [0, 0, 1, 1, 0, 0, -1, 0, 2, 0, 0, 0]),
    "grid": bytes([0]) + point_set(GRID),
    "grid_weighted_redundant": bytes([1]) + point_set(GRID, [0] * 5 + [-8] + [0] * 4 + [6] + [0] * 5),
    "square_edge_points": bytes([1]) + point_set(SQUARE_WITH_EDGE_POINTS, [0, 0, 0, 0, 1, 1, 1, 1, -3, 0]),
    "duplicates": bytes([0]) + point_set(DUPLICATES),
    "duplicates_weighted": bytes([1]) + point_set(DUPLICATES, [0, 1, 0, 0, 2, 0, -1, 0]),
    "collinear": bytes([1]) + point_set(COLLINEAR2, [1, 0, 0, 2, 0]),
    "jitter": bytes([0]) + point_set(JITTER),
    "huge_grid": bytes([1]) + point_set(GRID, [k % 3 for k in range(16)], e=496),
    "tiny_grid": bytes([1]) + point_set(GRID, [k % 3 for k in range(16)], e=-512),
    "decimals": bytes([0]) + point_set(DECIMALS),
    "three_points": bytes([1]) + point_set([small(0, 0), small(1, 0), small(0, 1)], [0, 0, 5]),
}

# ---- hull3 (fuzz/hull3_check.cpp): a 3D point set --------------------------------
COLLINEAR3 = [small(0, 0, 0), small(1, 1, 1), small(3, 3, 3), on_line(0, 2, -0.75), copy(1)]
DUPLICATES3 = [small(1, 1, 1), copy(0), small(-3, 2, 0), copy(2), small(5, -4, 2), copy(4), small(0, 0, 7), copy(0),
               small(2, 2, -6)]
EXTREMES3 = [special(1, 1, 1), special(17, 1, 3), special(1, 17, 2), special(10, 0, 0), special(0, 26, 10),
             special(11, 11, 27), special(27, 2, 1), special(6, 6, 6)]
HULL3 = {
    "cube": point_set(CUBE),
    "cube_face_centres": point_set(CUBE_FACE_CENTRES),
    "coplanar_plus_one": point_set(COPLANAR_PLUS_ONE),
    "coplanar": point_set(COPLANAR_PLUS_ONE[:6]),
    "collinear": point_set(COLLINEAR3),
    "grid3": point_set(GRID3),
    "jitter3": point_set(JITTER3),
    "sphere_lattice": point_set(SPHERE30[:24]),
    "duplicates3": point_set(DUPLICATES3),
    "extremes3": point_set(EXTREMES3),
    "huge_grid3": point_set(GRID3, e=992),
    "tiny_grid3": point_set(GRID3, e=-1024),
    "tetrahedron": point_set([small(0, 0, 0), small(1, 0, 0), small(0, 1, 0), small(0, 0, 1)]),
    "one_point": point_set([small(0, 0, 0)]),
    # Regression (found by fuzz_hull3, a wrong expectation of the check): points
    # 0 and 4 coincide at (-4, 2, -6); the SoS hull has 4 as its vertex there,
    # the strict view reports the location by its smallest index, 0 — as
    # strict_hull3.hpp documents. (The libFuzzer input as found: a point-set
    # byte stream cut short after 5 points.)
    "regression_strict_duplicate_vertex": bytes([8, 0, 0, 4, 10, 2, 4, 0, 8, 8, 15, 2, 0, 0, 10, 10, 2]),
    # Regression (CI's seed 5750008963199692262 of ghull_cuda_omp_test, stop
    # 85): subnormal coordinates beside ones near 1; the GPU hulls' scaled
    # line-1 keys underflowed, picked a fourth point on the plane of the first
    # three and handed the choice back to the host (kernels_cuda/spread.cuh
    # now repairs it by exact reductions; hull3_check requires no hand-back).
    "regression_subnormal_line1": point_set([
        raw(math.nextafter(1.0, 0.0), 0.0, 0.0),
        raw(math.nextafter(1.0, 0.0), math.nextafter(1.0, 2.0), 0.0),
        raw(-5e-324, 5e-324, 0.0),
        raw(0.0, 1.0, 5e-324)]),
}


# ---- rtd (fuzz/rtd_check.cpp): flags, a d-dimensional point set, U bytes ------------
# flags: bits 0-1 d - 2, bit 2 weighted, bits 3-4 the kind of U (0 W + δ, 1 fresh,
# 2 W permuted, 3 zero)
def rtd(d, points, weights=None, kind=0, e=0):
    flags = (d - 2) | (4 if weights is not None else 0) | (kind << 3)
    u = [(37 * i + 11) % 256 - 128 for i in range(len(points))]  # the U bytes k_i
    return bytes([flags]) + point_set(points, weights, e) + struct.pack("<%db" % len(u), *u)


def int8_points(d, n, seed):  # deterministic pseudo-random int8 points (a linear congruence)
    out, x = [], seed
    for _ in range(n):
        p = []
        for _ in range(d):
            x = (1103515245 * x + 12345) % (1 << 31)
            p.append((x >> 16) % 201 - 100)
        out.append(int8(*p))
    return out


AXES4 = [small(*[(3 if j == i else 0) * s for j in range(4)]) for i in range(4) for s in (1, -1)]
CUBE_CENTRE = CUBE + [small(1, 1, 1)]
GENERAL2 = [small(x, y) for x, y in [(7, 4), (-8, 1), (3, -7), (-4, 6), (0, -2), (5, 7), (-6, -5), (2, 3), (-1, 0), (6, -3)]]
RTD = {
    "d2_circle_lattice": rtd(2, CIRCLE12),
    "d2_grid_weighted_fresh": rtd(2, GRID, [k % 3 for k in range(16)], kind=1),
    "d2_general_position_fresh": rtd(2, GENERAL2, [0, 1, 2, 0, 3, 1, 0, 2, 1, 0], kind=1),
    "d2_general_position_delaunay": rtd(2, GENERAL2, [3, 0, 1, 2, 0, 1, 3, 0, 2, 1], kind=3),
    "d2_duplicates": rtd(2, DUPLICATES, [0, 1, 0, 0, 2, 0, -1, 0], kind=2),
    "d2_collinear": rtd(2, COLLINEAR2, [1, 0, 0, 2, 0]),
    "d2_huge_grid": rtd(2, GRID, [k % 3 for k in range(16)], e=496),
    "d3_tiny_cube": rtd(3, CUBE_CENTRE, [1] * 9, kind=1, e=-512),
    "d3_cube_centre": rtd(3, CUBE_CENTRE, [0] * 8 + [1], kind=3),
    "d3_sphere_lattice": rtd(3, SPHERE30[:12], kind=1),
    "d3_jitter": rtd(3, JITTER3, [0, 1, 0, 1, 0, 1, 0, 1], kind=0),
    "d3_int8": rtd(3, int8_points(3, 12, 1), [k % 5 for k in range(12)], kind=1),
    "d3_coplanar": rtd(3, COPLANAR_PLUS_ONE[:6]),
    "d4_axes_centre": rtd(4, AXES4[:4] + [small(0, 0, 0, 0)] + AXES4[4:], [0] * 4 + [2] + [0] * 4, kind=0),
    "d4_sphere_lattice": rtd(4, [lattice(b) for b in (0, 37, 66, 95, 124, 6, 40, 77, 101, 130)], kind=1),
    "d4_int8": rtd(4, int8_points(4, 10, 2), [k % 4 for k in range(10)], kind=2),
    "d4_hyperplane": rtd(4, [small(x, y, x + y, 0) for x in range(-1, 2) for y in range(2)]),
    "d5_int8": rtd(5, int8_points(5, 8, 3), [k % 3 for k in range(8)], kind=1),
    "d5_simplex_and_centre": rtd(5, [small(*[(4 if j == i else 0) for j in range(5)]) for i in range(5)]
                                 + [small(0, 0, 0, 0, 0), small(1, 1, 1, 1, 1)], kind=0),
}

# ---- rt3 (fuzz/rt3_check.cpp): flags (bit 0 weighted), a 3D point set ---------------
def rt3(points, weights=None, e=0):
    return bytes([1 if weights is not None else 0]) + point_set(points, weights, e)


RT3 = {
    "cube_centre": rt3(CUBE_CENTRE),
    "cube_centre_weighted": rt3(CUBE_CENTRE, [0] * 8 + [3]),
    "tiny_cube": rt3(CUBE_CENTRE, [1] * 9, e=-512),
    "sphere_lattice": rt3(SPHERE30[:20]),
    "jitter": rt3(JITTER3, [0, 1, 0, 1, 0, 1, 0, 1]),
    "int8": rt3(int8_points(3, 20, 1), [k % 5 for k in range(20)]),
    "int8_unweighted": rt3(int8_points(3, 24, 4)),
    "coplanar": rt3(COPLANAR_PLUS_ONE[:6]),
    "coplanar_plus_one": rt3(COPLANAR_PLUS_ONE),
    "grid_duplicates": rt3(CUBE + CUBE[:4], [k % 3 for k in range(12)]),
    "huge_cube": rt3(CUBE_CENTRE, [k % 2 for k in range(9)], e=496),
}

TARGETS = {
    "predicates": (PREDICATES, ".bin"),
    "read_points": (READ_POINTS, ".bin"),
    "read_indices": (READ_INDICES, ".bin"),
    "hull2": (HULL2, ".bin"),
    "certify": (CERTIFY, ".bin"),
    "kernels": (KERNELS, ".bin"),
    "rt2": (RT2, ".bin"),
    "hull3": (HULL3, ".bin"),
    "rtd": (RTD, ".bin"),
    "rt3": (RT3, ".bin"),
}


def main():
    for target, (seeds, ext) in TARGETS.items():
        out = os.path.join(CORPUS, target)
        os.makedirs(out, exist_ok=True)
        for name, data in sorted(seeds.items()):
            with open(os.path.join(out, name + ext), "wb") as f:
                f.write(data)
        print(f"{target}: wrote {len(seeds)} seeds to {out}")


if __name__ == "__main__":
    main()
