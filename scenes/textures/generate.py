#!/usr/bin/env python3
"""Generates the texture images used by ../textures.sc (pure standard library, deterministic).

Run from anywhere:  python3 scenes/textures/generate.py
Every image here is made by this script; nothing is copied from elsewhere.
"""
import math
import os
import random
import struct
import zlib

HERE = os.path.dirname(os.path.abspath(__file__))


def write_png(name, width, height, pixel):
    """pixel(x, y) -> (r, g, b) in 0..255, row 0 at the top."""
    raw = bytearray()
    for y in range(height):
        raw.append(0)  # filter: none
        for x in range(width):
            raw.extend(bytes(max(0, min(255, int(round(c)))) for c in pixel(x, y)))

    def chunk(kind, data):
        body = kind + data
        return struct.pack(">I", len(data)) + body + struct.pack(">I", zlib.crc32(body) & 0xFFFFFFFF)

    png = b"\x89PNG\r\n\x1a\n"
    png += chunk(b"IHDR", struct.pack(">IIBBBBB", width, height, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(bytes(raw), 9))
    png += chunk(b"IEND", b"")
    with open(os.path.join(HERE, name), "wb") as f:
        f.write(png)


def mix(a, b, t):
    return tuple(x + (y - x) * t for x, y in zip(a, b))


# checker.png: 64 x 64, 8 x 8 squares of cream and slate (the floor, repeated).
def checker(x, y):
    return (235, 225, 200) if ((x // 8) + (y // 8)) % 2 == 0 else (60, 80, 100)


# bricks.png: 128 x 64, four courses of bricks in running bond, grey mortar, each brick its own shade.
rng = random.Random(452)
BRICK_W, BRICK_H, MORTAR = 32, 16, 2
shades = {}


def bricks(x, y):
    row = y // BRICK_H
    xo = x + (BRICK_W // 2 if row % 2 else 0)
    col = (xo // BRICK_W) % (128 // BRICK_W)
    if y % BRICK_H < MORTAR or xo % BRICK_W < MORTAR:
        return (170, 165, 155)
    key = (row, col)
    if key not in shades:
        shades[key] = rng.uniform(0.75, 1.1)
    k = shades[key] * (0.93 + 0.07 * math.sin(x * 1.7 + y * 2.3))  # a little grain
    return (165 * k, 70 * k, 45 * k)


# world.png: 256 x 128 equirectangular "planet": made-up continents from smooth value noise,
# ice caps at the top and bottom rows (the poles: v = 0 is the top pole on a sphere), and a
# graticule every 30 degrees. The noise wraps around in x so there is no seam.
W, H = 256, 128
nrng = random.Random(7)
GRID = 8
lattice = [[nrng.random() for _ in range(GRID)] for _ in range(GRID // 2 + 1)]


def smooth(t):
    return t * t * (3 - 2 * t)


def noise(x, y, freq):
    gx = x / W * freq
    gy = y / H * freq / 2
    x0, y0 = int(math.floor(gx)), int(math.floor(gy))
    tx, ty = smooth(gx - x0), smooth(gy - y0)

    def at(i, j):
        return lattice[min(j, len(lattice) - 1) % len(lattice)][i % GRID]

    a = at(x0, y0) + (at(x0 + 1, y0) - at(x0, y0)) * tx
    b = at(x0, y0 + 1) + (at(x0 + 1, y0 + 1) - at(x0, y0 + 1)) * tx
    return a + (b - a) * ty


def world(x, y):
    lat = 90 - (y + 0.5) / H * 180
    lon = (x + 0.5) / W * 360 - 180
    h = 0.65 * noise(x, y, GRID) + 0.35 * noise((x * 2) % W, (y * 2) % H, GRID)
    if abs(lat) > 72:
        c = (240, 245, 250)
    elif h > 0.5:
        c = mix((70, 140, 60), (150, 120, 70), min(1, (h - 0.5) * 4))
    else:
        c = mix((20, 50, 130), (40, 100, 170), h / 0.5)
    on_grid = abs(lat) % 30 < 180 / H or abs(lon) % 30 < 360 / W
    return mix(c, (255, 255, 255), 0.35) if on_grid else c


# stripes.png: 64 x 64, vertical candy stripes (u runs around a cone) with a yellow band near
# the top rows (v small: the apex end of the side, the top of a cube face).
def stripes(x, y):
    if 6 <= y < 12:
        return (250, 210, 40)
    return (220, 40, 60) if (x // 8) % 2 == 0 else (245, 240, 235)


# letter.png: 64 x 64, a dark "F" on a light tile with a red top edge and a blue left edge:
# the F is not symmetric, so it shows at a glance whether a face is upright or mirrored.
def letter(x, y):
    if y < 4:
        return (200, 40, 40)
    if x < 4:
        return (40, 70, 200)
    in_f = (16 <= x < 24 and 12 <= y < 52) or (16 <= x < 48 and 12 <= y < 20) or (16 <= x < 40 and 28 <= y < 36)
    return (30, 30, 35) if in_f else (230, 225, 210)


write_png("checker.png", 64, 64, checker)
write_png("bricks.png", 128, 64, bricks)
write_png("world.png", W, H, world)
write_png("stripes.png", 64, 64, stripes)
write_png("letter.png", 64, 64, letter)
