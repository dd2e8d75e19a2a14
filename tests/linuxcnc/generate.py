#!/usr/bin/env python3
"""Generate random milling programmes in the G-code subset that both ncsight's fanuc0m profile
and LinuxCNC's rs274 read the same way: G21, G17/G18/G19, G90/G91, G00, G01, G02/G03 with R or
centre words, every number with a decimal point. Deterministic for a given seed.

usage: generate.py OUTDIR COUNT [SEED]
"""
import math
import os
import random
import sys



def programme(rng):
    lines = ["G21 G17 G90", "F{:.1f}".format(rng.uniform(50, 2000))]
    pos = [0.0, 0.0, 0.0]
    plane = 17
    incremental = False
    for _ in range(rng.randint(5, 25)):
        r = rng.random()
        if r < 0.1:
            plane = rng.choice([17, 18, 19])
            lines.append(f"G{plane}")
            continue
        if r < 0.2:
            incremental = not incremental
            lines.append("G91" if incremental else "G90")
            continue
        kind = rng.choice(["G00", "G01", "G02", "G03", "G02", "G03"])
        axes = {17: (0, 1, 2), 18: (2, 0, 1), 19: (1, 2, 0)}[plane]
        if kind in ("G00", "G01"):
            target = [round(pos[i] + rng.uniform(-50, 50), 3) for i in range(3)]
            words = [kind]
            for i, name in enumerate("XYZ"):
                if rng.random() < 0.8 or i == 0:
                    v = target[i] - pos[i] if incremental else target[i]
                    words.append(f"{name}{v:.3f}")
                else:
                    target[i] = pos[i]
            if kind == "G01" and rng.random() < 0.3:
                words.append("F{:.1f}".format(rng.uniform(50, 2000)))
            lines.append(" ".join(words))
            pos = target
            continue
        # Arc: choose a centre and an end angle on the circle, so the data is exact.
        a, b, n = axes
        radius = rng.uniform(2, 40)
        start_ang = rng.uniform(0, 2 * math.pi)
        ca = pos[a] - radius * math.cos(start_ang)
        cb = pos[b] - radius * math.sin(start_ang)
        sweep = rng.uniform(0.2, 2 * math.pi - 0.2)
        ccw = kind == "G03"
        end_ang = start_ang + (sweep if ccw else -sweep)
        target = list(pos)
        target[a] = round(ca + radius * math.cos(end_ang), 3)
        target[b] = round(cb + radius * math.sin(end_ang), 3)
        if rng.random() < 0.3:
            target[n] = round(pos[n] + rng.uniform(-10, 10), 3)
        words = [kind]
        for i, name in enumerate("XYZ"):
            if target[i] != pos[i] or i in (a, b):
                v = target[i] - pos[i] if incremental else target[i]
                words.append(f"{name}{v:.3f}")
        use_r = rng.random() < 0.4
        if use_r:
            # Recompute the centre from the rounded end point so both tools agree on it.
            r_word = radius if sweep <= math.pi else -radius
            # Skip near-semicircles, where the centre is ill-conditioned.
            if abs(sweep - math.pi) < 0.3:
                use_r = False
            else:
                words.append(f"R{r_word:.4f}")
        if not use_r:
            # Exact centre words; the end point was rounded, so re-place the centre on the
            # perpendicular bisector at the chosen radius is unnecessary: keep rounding tiny.
            ci = "IJK"[a]
            cj = "IJK"[b]
            words.append(f"{ci}{ca - pos[a]:.4f}")
            words.append(f"{cj}{cb - pos[b]:.4f}")
        lines.append(" ".join(words))
        pos = target
    lines.append("M30")
    return "\n".join(lines) + "\n"


def main():
    out, count = sys.argv[1], int(sys.argv[2])
    seed = int(sys.argv[3]) if len(sys.argv) > 3 else 2026
    rng = random.Random(seed)
    os.makedirs(out, exist_ok=True)
    for k in range(count):
        with open(os.path.join(out, f"random_{k:03d}.ngc"), "w") as f:
            f.write(programme(rng))


if __name__ == "__main__":
    main()
