#!/usr/bin/env python3
"""Generate random drilling programmes in the subset where FANUC 0-M and LinuxCNC agree, each
twice: `NAME.nc` in FANUC spelling (K repeats, P dwell in ms) for ncsight's fanuc0m profile,
`NAME.ngc` in LinuxCNC spelling (L repeats, P in seconds) for rs274.

Kept out on purpose (the two controllers differ, see docs/commands/drilling.md): G89 under G98
(LinuxCNC feeds out to the clearance plane, FANUC to R then rapids), G98/G99 changed while a
cycle is in force, modal G91 continuation blocks under G99, R above the initial level, G84, G74,
G76, G86, G87, G88 and K0.

usage: generate_drill.py OUTDIR COUNT [SEED]
"""
import os
import random
import sys


def f(v):
    return f"{v:.3f}"


def programme(rng):
    fanuc, cnc = [], []

    def both(line, lcnc=None):
        fanuc.append(line)
        cnc.append(lcnc if lcnc is not None else line)

    plane = rng.choice([17, 18, 19])
    a, b, n = {17: ("X", "Y", "Z"), 18: ("Z", "X", "Y"), 19: ("Y", "Z", "X")}[plane]
    both(f"G21 G{plane} G90")
    both(f"F{rng.uniform(50, 800):.1f}")
    pos = {a: 0.0, b: 0.0, n: rng.uniform(15, 30)}
    both(f"G00 {a}{f(pos[a])} {b}{f(pos[b])} {n}{f(pos[n])}")
    for _ in range(rng.randint(1, 4)):
        kind = rng.choice(["G81", "G82", "G83", "G73", "G85", "G89"])
        ret = rng.choice(["G98", "G99"])
        if kind == "G89":
            ret = "G99"
        incremental = rng.random() < 0.3
        if incremental and ret == "G99":
            holes = 1
        else:
            holes = rng.randint(1, 4)
        initial = pos[n]
        r_abs = initial - rng.uniform(1, 10)
        z_abs = r_abs - rng.uniform(1, 20)
        q = rng.uniform(0.5, 5)
        p_ms = rng.choice([100, 250, 500, 1000])
        if incremental:
            both("G91")
        for h in range(holes):
            da, db = rng.uniform(-30, 30), rng.uniform(-30, 30)
            words = []
            if h == 0:
                words += [ret, kind]
            if incremental:
                words += [f"{a}{f(da)}", f"{b}{f(db)}"]
            else:
                words += [f"{a}{f(pos[a] + da)}", f"{b}{f(pos[b] + db)}"]
            if h == 0 or rng.random() < 0.3:
                if h > 0:
                    z_abs = r_abs - rng.uniform(1, 20)
                zi = z_abs - r_abs if incremental else z_abs
                words.append(f"{n}{f(zi)}")
            if h == 0:
                ri = r_abs - initial if incremental else r_abs
                words.append(f"R{f(ri)}")
            if kind in ("G73", "G83") and (h == 0 or rng.random() < 0.3):
                q = rng.uniform(0.5, 5)
                words.append(f"Q{f(q)}")
            fw, cw = list(words), list(words)
            if kind in ("G82", "G89") and h == 0:
                fw.append(f"P{p_ms}")
                cw.append(f"P{p_ms / 1000:.3f}")
            reps = 1
            if rng.random() < 0.3:
                reps = rng.randint(2, 4)
                fw.append(f"K{reps}")
                cw.append(f"L{reps}")
            both(" ".join(fw), " ".join(cw))
            for _ in range(reps):
                if incremental:
                    pos[a] += da
                    pos[b] += db
                else:
                    pos[a], pos[b] = pos[a] + da, pos[b] + db
            pos[n] = initial if ret == "G98" else r_abs
        both("G80")
        if incremental:
            both("G90")
        pos[n] = pos[n] + rng.uniform(0, 10)
        both(f"G00 {n}{f(pos[n])}")
    both("M30", "M2")
    return "\n".join(fanuc) + "\n", "\n".join(cnc) + "\n"


def main():
    out, count = sys.argv[1], int(sys.argv[2])
    seed = int(sys.argv[3]) if len(sys.argv) > 3 else 2027
    rng = random.Random(seed)
    os.makedirs(out, exist_ok=True)
    for k in range(count):
        nc, ngc = programme(rng)
        base = os.path.join(out, f"drill_{k:03d}")
        open(base + ".nc", "w").write(nc)
        open(base + ".ngc", "w").write(ngc)


if __name__ == "__main__":
    main()
