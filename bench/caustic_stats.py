# caustic_stats.py: the caustic of an image, in numbers: where it is (the brightness-weighted centroid,
# in pixels), how big (the RMS radius about it, and the radius holding half its light), how bright (the
# sum of the pixels), and its peak. Pure Python (no numpy): reads PFM (whitted's linear output) and
# Radiance HDR (POV-Ray's +FH).
#
#   python3 bench/caustic_stats.py IMAGE.pfm|IMAGE.hdr [ROWS_FROM]
#   python3 bench/caustic_stats.py --error IMAGE REFERENCE   (the relative RMS error of IMAGE)
#
# ROWS_FROM: only rows from this one down (the floor under the ball; the ball itself is above).
import math
import struct
import sys


def load_pfm(path):
    with open(path, 'rb') as f:
        kind = f.readline().strip()
        w, h = map(int, f.readline().split())
        scale = float(f.readline())
        n = 3 if kind == b'PF' else 1
        data = struct.unpack(('<' if scale < 0 else '>') + 'f' * (w * h * n), f.read(4 * w * h * n))
    rows = []
    for y in range(h):  # PFM rows go bottom up
        r = data[(h - 1 - y) * w * n:(h - y) * w * n]
        rows.append([sum(r[x * n:(x + 1) * n]) / n for x in range(w)])
    return rows


def load_hdr(path):
    with open(path, 'rb') as f:
        data = f.read()
    pos = 0
    while True:  # the header, to an empty line, then the resolution line
        end = data.index(b'\n', pos)
        line = data[pos:end]
        pos = end + 1
        if line == b'':
            break
    end = data.index(b'\n', pos)
    parts = data[pos:end].split()
    pos = end + 1
    h, w = int(parts[1]), int(parts[3])
    rows = []
    for _ in range(h):
        scan = [[0] * 4 for _ in range(w)]
        if data[pos] == 2 and data[pos + 1] == 2 and (data[pos + 2] << 8 | data[pos + 3]) == w:
            pos += 4
            for c in range(4):  # new-style run-length encoding, a component at a time
                x = 0
                while x < w:
                    count = data[pos]
                    pos += 1
                    if count > 128:
                        count -= 128
                        for i in range(count):
                            scan[x + i][c] = data[pos]
                        pos += 1
                    else:
                        for i in range(count):
                            scan[x + i][c] = data[pos + i]
                        pos += count
                    x += count
        else:
            for x in range(w):
                scan[x] = list(data[pos:pos + 4])
                pos += 4
        row = []
        for r, g, b, e in scan:
            f = math.ldexp(1.0, e - 136) if e else 0.0
            row.append((r + g + b) * f / 3)
        rows.append(row)
    return rows


def stats(rows, row_from=0):
    total = sx = sy = 0.0
    peak = 0.0
    pixels = []
    for y in range(row_from, len(rows)):
        for x, v in enumerate(rows[y]):
            if v <= 0:
                continue
            total += v
            sx += v * (x + 0.5)
            sy += v * (y + 0.5)
            peak = max(peak, v)
            pixels.append((x + 0.5, y + 0.5, v))
    cx, cy = sx / total, sy / total
    r2 = sum(v * ((x - cx) ** 2 + (y - cy) ** 2) for x, y, v in pixels) / total
    by_radius = sorted(((x - cx) ** 2 + (y - cy) ** 2, v) for x, y, v in pixels)
    run, r50 = 0.0, 0.0
    for d2, v in by_radius:
        run += v
        if run >= total / 2:
            r50 = math.sqrt(d2)
            break
    return {'total': total, 'cx': cx, 'cy': cy, 'rms': math.sqrt(r2), 'r50': r50, 'peak': peak}


def load(path):
    return load_pfm(path) if path.endswith('.pfm') else load_hdr(path)


if __name__ == '__main__':
    if sys.argv[1] == '--error':
        a, b = load(sys.argv[2]), load(sys.argv[3])
        se = sum((x - y) ** 2 for ra, rb in zip(a, b) for x, y in zip(ra, rb))
        print('%.4f' % math.sqrt(se / sum(y * y for rb in b for y in rb)))
        sys.exit(0)
    path = sys.argv[1]
    rows = load_pfm(path) if path.endswith('.pfm') else load_hdr(path)
    s = stats(rows, int(sys.argv[2]) if len(sys.argv) > 2 else 0)
    print('\t'.join('%s=%.4g' % (k, v) for k, v in s.items()))
