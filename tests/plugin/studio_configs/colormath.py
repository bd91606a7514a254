"""Tiny pure-python colour maths used by make_configs.py (no numpy needed)."""
import math

# --- 3x3 matrix helpers ------------------------------------------------------

def mmul(a, b):
    return [[sum(a[i][k] * b[k][j] for k in range(3)) for j in range(3)] for i in range(3)]

def mvec(a, v):
    return [sum(a[i][k] * v[k] for k in range(3)) for i in range(3)]

def minv(m):
    a, b, c = m[0]
    d, e, f = m[1]
    g, h, i = m[2]
    det = a * (e * i - f * h) - b * (d * i - f * g) + c * (d * h - e * g)
    return [[(e * i - f * h) / det, (c * h - b * i) / det, (b * f - c * e) / det],
            [(f * g - d * i) / det, (a * i - c * g) / det, (c * d - a * f) / det],
            [(d * h - e * g) / det, (b * g - a * h) / det, (a * e - b * d) / det]]

def xy_to_XYZ(xy):
    x, y = xy
    return [x / y, 1.0, (1.0 - x - y) / y]

def rgb_to_xyz(prim, white):
    """prim = [(xr,yr),(xg,yg),(xb,yb)], white=(xw,yw). Standard SMPTE RP 177 derivation."""
    cols = [xy_to_XYZ(p) for p in prim]
    m = [[cols[j][i] for j in range(3)] for i in range(3)]
    s = mvec(minv(m), xy_to_XYZ(white))
    return [[m[i][j] * s[j] for j in range(3)] for i in range(3)]

BRADFORD = [[0.8951, 0.2664, -0.1614],
            [-0.7502, 1.7135, 0.0367],
            [0.0389, -0.0685, 1.0296]]

def cat_bradford(src_white, dst_white):
    ws = mvec(BRADFORD, xy_to_XYZ(src_white))
    wd = mvec(BRADFORD, xy_to_XYZ(dst_white))
    d = [[wd[0] / ws[0], 0, 0], [0, wd[1] / ws[1], 0], [0, 0, wd[2] / ws[2]]]
    return mmul(minv(BRADFORD), mmul(d, BRADFORD))

def m44(m):
    """3x3 -> OCIO 16-float row-major list."""
    return [m[0][0], m[0][1], m[0][2], 0.0,
            m[1][0], m[1][1], m[1][2], 0.0,
            m[2][0], m[2][1], m[2][2], 0.0,
            0.0, 0.0, 0.0, 1.0]

def fmt_m44(m):
    return "[" + ", ".join("%.12g" % v for v in m44(m)) + "]"

# --- chromaticities ------------------------------------------------------------
D65 = (0.3127, 0.3290)
ACES_WHITE = (0.32168, 0.33767)
E_WHITE = (1.0 / 3.0, 1.0 / 3.0)

REC709 = [(0.64, 0.33), (0.30, 0.60), (0.15, 0.06)]
REC2020 = [(0.708, 0.292), (0.170, 0.797), (0.131, 0.046)]
P3 = [(0.680, 0.320), (0.265, 0.690), (0.150, 0.060)]
SGAMUT3_CINE = [(0.766, 0.275), (0.225, 0.800), (0.089, -0.087)]
AP0 = [(0.7347, 0.2653), (0.0, 1.0), (0.0001, -0.0770)]
AP1 = [(0.713, 0.293), (0.165, 0.830), (0.128, 0.044)]

# --- 1D transfer functions (encoded -> linear) ---------------------------------

def srgb_to_lin(x):  # IEC 61966-2-1 piecewise
    return x / 12.92 if x <= 0.04045 else ((x + 0.055) / 1.055) ** 2.4

def lin_to_srgb(x):
    return x * 12.92 if x <= 0.0031308 else 1.055 * x ** (1 / 2.4) - 0.055

def rec709_to_lin(x):  # inverse of ITU-R BT.709 OETF
    return x / 4.5 if x < 0.081 else ((x + 0.099) / 1.099) ** (1 / 0.45)

def cineon_to_lin(x, black=95.0, white=685.0, gamma=0.6, dens=0.002):
    off = 10.0 ** ((black - white) * dens / gamma)
    return (10.0 ** ((1023.0 * x - white) * dens / gamma) - off) / (1.0 - off)

def panalog_to_lin(x):  # Nuke's published Panalog formula
    return (10.0 ** ((1023.0 * x - 681.0) / 444.0) - 0.0408) / (1.0 - 0.0408)

def redlog_to_lin(x):  # Nuke's REDLog
    return (10.0 ** ((1023.0 * x - 1023.0) / 511.0) - 0.01) / (1.0 - 0.01)

def viperlog_to_lin(x):  # Nuke's ViperLog
    return 10.0 ** ((1023.0 * x - 1023.0) / 500.0)

def logc3_to_lin(t):  # ARRI LogC v3, EI 800 (scene-linear, 0.18 grey)
    cut, a, b, c, d, e, f = 0.010591, 5.555556, 0.052272, 0.247190, 0.385537, 5.367655, 0.092809
    return (10.0 ** ((t - d) / c) - b) / a if t > e * cut + f else (t - f) / e

def ploglin_to_lin(x):  # Josh Pines log: ref white 445, ref lin 0.18, 0.002 dens/cv, neg gamma 0.6
    return 0.18 * 10.0 ** ((1023.0 * x - 445.0) * 0.002 / 0.6)

def slog_to_lin(x):  # Sony S-Log (plain formula, no legal range, no reflection scaling)
    return 10.0 ** ((x - 0.616596 - 0.03) / 0.432699) - 0.037584

def slog1_to_lin(y):  # Sony S-Log1 10-bit legal code value, reflection out (x0.9)
    x = (y * 1023.0 - 64.0) / 876.0
    if x >= 0.030001222851889303:
        v = 10.0 ** ((x - 0.616596 - 0.03) / 0.432699) - 0.037584
    else:
        v = (x - 0.030001222851889303) / 5.0
    return v * 0.9

def slog2_to_lin(y):
    return slog1_to_lin(y) * 219.0 / 155.0

def slog3_to_lin(y):  # Sony S-Log3 technical summary
    if y >= 171.2102946929 / 1023.0:
        return 10.0 ** ((y * 1023.0 - 420.0) / 261.5) * (0.18 + 0.01) - 0.01
    return (y * 1023.0 - 95.0) * 0.01125 / (171.2102946929 - 95.0)

def clog_to_lin(v):  # Nuke's Canon Log formula
    if v >= 0.0730597:
        return (10.0 ** ((v - 0.0730597) / 0.529136) - 1.0) / 10.1596
    return -(10.0 ** ((0.0730597 - v) / 0.529136) - 1.0) / 10.1596

def protune_to_lin(v):  # GoPro Protune (Nuke)
    return (113.0 ** v - 1.0) / 112.0

# --- LUT writers --------------------------------------------------------------

def write_spi1d(path, fn, lo=-0.125, hi=1.125, n=4096):
    with open(path, "w") as f:
        f.write("Version 1\nFrom %r %r\nLength %d\nComponents 1\n{\n" % (lo, hi, n))
        for i in range(n):
            x = lo + (hi - lo) * i / (n - 1)
            f.write("    %.9g\n" % fn(x))
        f.write("}\n")

def write_cube3d(path, fn, size, title):
    """fn(r,g,b)->(r,g,b); .cube order: red fastest."""
    with open(path, "w") as f:
        f.write('TITLE "%s"\nLUT_3D_SIZE %d\nDOMAIN_MIN 0.0 0.0 0.0\nDOMAIN_MAX 1.0 1.0 1.0\n' % (title, size))
        for bi in range(size):
            for gi in range(size):
                for ri in range(size):
                    o = fn(ri / (size - 1.0), gi / (size - 1.0), bi / (size - 1.0))
                    f.write("%.8g %.8g %.8g\n" % tuple(o))
