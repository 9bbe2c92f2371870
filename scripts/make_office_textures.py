#!/usr/bin/env python3
"""Writes the textures of maps/office (docs/sim.md): office wall panels, a carpet and eight posters
unlike the lab's random-shape posters (a bar chart, rings, a calendar, an exit sign, a notice board,
a floor plan, a wall clock, a whiteboard). Standard library only; deterministic.

    python3 scripts/make_office_textures.py maps/office/textures
"""
import math
import os
import random
import struct
import sys
import zlib

SIZE = 256


class Canvas:
    """A 256 × 256 grey image (written as RGB PNG); values 0..255."""

    def __init__(self, grey):
        self.px = bytearray([grey]) * (SIZE * SIZE)

    def put(self, x, y, g):
        if 0 <= x < SIZE and 0 <= y < SIZE:
            self.px[y * SIZE + x] = max(0, min(255, int(g)))

    def rect(self, x0, y0, w, h, g):
        for y in range(max(0, y0), min(SIZE, y0 + h)):
            for x in range(max(0, x0), min(SIZE, x0 + w)):
                self.px[y * SIZE + x] = g

    def disc(self, cx, cy, r, g):
        for y in range(int(cy - r), int(cy + r) + 1):
            for x in range(int(cx - r), int(cx + r) + 1):
                if (x - cx) ** 2 + (y - cy) ** 2 <= r * r:
                    self.put(x, y, g)

    def ring(self, cx, cy, r_in, r_out, g):
        for y in range(int(cy - r_out), int(cy + r_out) + 1):
            for x in range(int(cx - r_out), int(cx + r_out) + 1):
                if r_in * r_in <= (x - cx) ** 2 + (y - cy) ** 2 <= r_out * r_out:
                    self.put(x, y, g)

    def polygon(self, pts, g):
        ys = [p[1] for p in pts]
        for y in range(max(0, int(min(ys))), min(SIZE, int(max(ys)) + 1)):
            xs = []
            for (ax, ay), (bx, by) in zip(pts, pts[1:] + pts[:1]):
                if (ay <= y + 0.5 < by) or (by <= y + 0.5 < ay):
                    xs.append(ax + (y + 0.5 - ay) * (bx - ax) / (by - ay))
            xs.sort()
            for a, b in zip(xs[::2], xs[1::2]):
                for x in range(int(math.ceil(a - 0.5)), int(math.floor(b - 0.5)) + 1):
                    self.put(x, y, g)

    def line(self, x0, y0, x1, y1, width, g):
        dx, dy = x1 - x0, y1 - y0
        n = math.hypot(dx, dy) or 1.0
        ox, oy = -dy / n * width / 2, dx / n * width / 2
        self.polygon([(x0 + ox, y0 + oy), (x1 + ox, y1 + oy), (x1 - ox, y1 - oy),
                      (x0 - ox, y0 - oy)], g)

    def noise(self, amplitude, seed):
        rng = random.Random(seed)
        for i in range(SIZE * SIZE):
            self.px[i] = max(0, min(255, self.px[i] + rng.randint(-amplitude, amplitude)))

    def write(self, path):
        raw = b"".join(b"\x00" + bytes(v for g in self.px[y * SIZE:(y + 1) * SIZE]
                                       for v in (g, g, g)) for y in range(SIZE))

        def chunk(tag, data):
            return (struct.pack(">I", len(data)) + tag + data +
                    struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF))

        header = struct.pack(">IIBBBBB", SIZE, SIZE, 8, 2, 0, 0, 0)
        with open(path, "wb") as f:
            f.write(b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", header) +
                    chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def wall_panels():
    c = Canvas(168)
    c.noise(6, 31)
    for x in range(0, SIZE, 64):  # panel seams every 64 texels
        c.rect(x, 0, 2, SIZE, 150)
    c.rect(0, 126, SIZE, 3, 140)  # a rail at mid height
    return c


def carpet():
    c = Canvas(72)
    c.noise(14, 32)
    rng = random.Random(33)
    for _ in range(400):
        c.disc(rng.randrange(SIZE), rng.randrange(SIZE), rng.uniform(0.8, 2.0), rng.choice((45, 100)))
    return c


def chart():
    c = Canvas(240)
    c.rect(30, 20, 6, 210, 20)  # axes
    c.rect(30, 224, 210, 6, 20)
    rng = random.Random(41)
    for i in range(6):
        h = rng.randint(40, 190)
        c.rect(50 + i * 31, 224 - h, 22, h, 30 if i % 2 else 90)
    return c


def rings():
    c = Canvas(25)
    for k, r in enumerate(range(100, 10, -18)):
        c.disc(110, 120, r, 235 if k % 2 == 0 else 25)
    c.polygon([(180, 30), (245, 30), (245, 95)], 235)
    c.rect(170, 200, 70, 40, 235)
    return c


def calendar():
    c = Canvas(235)
    c.rect(0, 0, SIZE, 46, 30)  # the month's header
    c.rect(40, 14, 120, 18, 235)
    rng = random.Random(43)
    for row in range(5):
        for col in range(7):
            x, y = 6 + col * 35, 54 + row * 40
            c.rect(x, y, 32, 36, 30)
            c.rect(x + 3, y + 3, 26, 30, 235 if rng.random() > 0.25 else 120)
    return c


def block_letters(c, text, x, y, scale, g):
    """Blocky capitals E, X, I, T on a 5 × 7 grid."""
    glyphs = {
        "E": ["11111", "10000", "10000", "11110", "10000", "10000", "11111"],
        "X": ["10001", "10001", "01010", "00100", "01010", "10001", "10001"],
        "I": ["11111", "00100", "00100", "00100", "00100", "00100", "11111"],
        "T": ["11111", "00100", "00100", "00100", "00100", "00100", "00100"],
    }
    for k, ch in enumerate(text):
        for r, bits in enumerate(glyphs[ch]):
            for col, b in enumerate(bits):
                if b == "1":
                    c.rect(x + (k * 6 + col) * scale, y + r * scale, scale, scale, g)


def exit_sign():
    c = Canvas(35)
    c.rect(10, 10, 236, 236, 70)
    block_letters(c, "EXIT", 18, 30, 9, 245)
    c.polygon([(40, 170), (150, 170), (150, 140), (215, 190), (150, 240), (150, 210), (40, 210)],
              245)
    return c


def notice_board():
    c = Canvas(120)
    rng = random.Random(45)
    for _ in range(7):
        w, h = rng.randint(60, 100), rng.randint(50, 90)
        x, y = rng.randint(0, SIZE - w), rng.randint(0, SIZE - h)
        c.rect(x, y, w, h, 245)
        for k in range(6, h - 10, 12):
            c.rect(x + 8, y + k, rng.randint(w // 3, w - 16), 5, 30)
        c.disc(x + w // 2, y + 4, 4, 10)
    return c


def floor_plan():
    c = Canvas(245)
    c.rect(14, 14, 228, 228, 20)
    c.rect(22, 22, 212, 212, 245)
    for (x0, y0, x1, y1) in [(22, 110, 140, 110), (140, 22, 140, 180), (90, 180, 234, 180),
                             (60, 110, 60, 234)]:
        c.line(x0, y0, x1, y1, 7, 20)
    c.disc(190, 70, 22, 20)
    c.polygon([(80, 40), (120, 40), (100, 80)], 20)
    return c


def clock():
    c = Canvas(200)
    c.disc(128, 128, 120, 20)
    c.disc(128, 128, 108, 240)
    for h in range(12):
        a = h * math.pi / 6
        r0 = 84 if h % 3 else 72
        c.line(128 + r0 * math.sin(a), 128 - r0 * math.cos(a), 128 + 100 * math.sin(a),
               128 - 100 * math.cos(a), 8 if h % 3 else 14, 20)
    c.line(128, 128, 128 + 55 * math.sin(2.2), 128 - 55 * math.cos(2.2), 12, 20)
    c.line(128, 128, 128 + 90 * math.sin(5.1), 128 - 90 * math.cos(5.1), 7, 20)
    return c


def whiteboard():
    c = Canvas(80)
    c.rect(8, 8, 240, 240, 245)
    rng = random.Random(47)
    for _ in range(5):  # marker scribbles
        x, y = rng.randint(20, 120), rng.randint(30, 220)
        pts = [(x, y)]
        for _ in range(5):
            x, y = x + rng.randint(10, 30), y + rng.randint(-25, 25)
            pts.append((x, y))
        for (a, b), (p, q) in zip(pts, pts[1:]):
            c.line(a, b, p, q, 5, 25)
    c.rect(150, 40, 80, 50, 25)
    c.ring(190, 180, 25, 34, 25)
    return c


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "maps/office/textures"
    os.makedirs(out, exist_ok=True)
    for name, make in [("wall_panels", wall_panels), ("carpet", carpet), ("chart", chart),
                       ("rings", rings), ("calendar", calendar), ("exit_sign", exit_sign),
                       ("notice_board", notice_board), ("floor_plan", floor_plan),
                       ("clock", clock), ("whiteboard", whiteboard)]:
        make().write(os.path.join(out, name + ".png"))
        print(os.path.join(out, name + ".png"))


if __name__ == "__main__":
    main()
