#!/usr/bin/env python3
"""Near-degenerate and extreme inputs through the CLI, as a user would meet them: nearly
degenerate site sets (collinear, cocircular, grids, equal weights; moved by an ulp, 1e-15, 1e-12,
1e-9 or not at all; at 1 and at 1e7) and extreme values through `diagram` and `check`;
translated, rotated and scaled graphs and the near-degenerate diagrams through `recognize`
(position and weight errors against the generating sites); a graph with two site labels swapped;
graphs rounded to 15, 12, 9 and 6 digits.

Usage: python3 bench/exactness_probe.py build/cli/covmap [engine] [recognize] [labels] [rounded]
Prints one line per case; the engine section ends with the number of diagrams written wrongly
(exit 0 from `diagram` but rejected by `check`, or any exit but 0 and 2). Exit status 1 when that
number is not 0. The generated files stay in the temporary probe-* folder the lines name, for
inspection."""
import json, math, os, random, subprocess, sys, tempfile
COVMAP = sys.argv[1]
SECTIONS = sys.argv[2:] or ["engine", "recognize", "labels", "rounded"]
work = tempfile.mkdtemp(prefix="probe-")

def run(*args):
    p = subprocess.run([COVMAP, *args], capture_output=True, text=True)
    return p.returncode, (p.stdout + p.stderr).strip().splitlines()

def write_sites(name, sites):
    path = os.path.join(work, name + ".csv")
    with open(path, "w") as f:
        f.write("id,x,y,weight\n")
        for i, (x, y, w) in enumerate(sites):
            f.write(f"{i},{x!r},{y!r},{w!r}\n")
    return path

def perturb(v, rel, rng):
    if rel is None:
        return math.nextafter(v, math.inf) if rng.random() < 0.5 else math.nextafter(v, -math.inf)
    return v * (1 + rng.choice([-1, 1]) * rel) if rel else v

def families(rng):
    rels = [("ulp", None), ("1e-15", 1e-15), ("1e-12", 1e-12), ("1e-9", 1e-9), ("exact", 0)]
    for tag, rel in rels:
        for scale in [1.0, 1e7]:
            # collinear on y = x/2
            s = []
            for i in range(20):
                x = rng.uniform(0, 100) * scale + (scale if scale > 1 else 0)
                s.append((x, perturb(x / 2, rel, rng), rng.uniform(1, 3)))
            yield f"collinear-{tag}-s{scale:g}", s
            # cocircular, equal weights and random weights
            for wname in ["eq", "rand"]:
                s = []
                for i in range(16):
                    a = rng.uniform(0, 2 * math.pi)
                    x, y = scale + 50 * math.cos(a), scale + 50 * math.sin(a)
                    s.append((perturb(x, rel, rng), perturb(y, rel, rng), 1.0 if wname == "eq" else rng.uniform(1, 2)))
                yield f"cocircular-{wname}-{tag}-s{scale:g}", s
            # integer grid, small integer weights
            s = []
            for i in range(6):
                for j in range(6):
                    s.append((perturb(scale + 10.0 * i, rel, rng), perturb(scale + 10.0 * j, rel, rng), float(rng.randint(1, 3))))
            yield f"grid-{tag}-s{scale:g}", s
            # equal weights random
            s = [(perturb(scale + rng.uniform(0, 100), rel, rng), perturb(scale + rng.uniform(0, 100), rel, rng), perturb(1.0, rel, rng)) for _ in range(30)]
            yield f"equalw-{tag}-s{scale:g}", s

def extremes():
    yield "coords-1e15", [(1e15 + 1000 * i, 1e15 + 700 * ((i * 7) % 5), 1 + 0.1 * i) for i in range(8)]
    yield "one-ulp-apart", [(1.0, 1.0, 1.0), (math.nextafter(1.0, 2), 1.0, 1.5), (0.0, 0.0, 2.0), (3.0, 1.0, 1.2)]
    yield "denormal-coords", [(5e-324 * i, 5e-324 * ((i * 3) % 4), 1 + i) for i in range(1, 6)]
    yield "denormal-weights", [(i, (i * 3) % 4, 5e-324 * i) for i in range(1, 6)]
    yield "mixed-scales", [(1e300, 0, 1), (1e-300, 0, 2), (0, 1e-300, 1.5), (-1e300, 1, 1)]
    yield "huge-1e308", [(1e308, 0, 1), (-1e308, 0, 2), (0, 1e308, 1.5), (0, -1e308, 1)]

def engine():
    rng = random.Random(11)
    bad = 0
    for name, s in list(families(rng)) + list(extremes()):
        path = write_sites(name, s)
        out = path[:-4] + ".json"
        rc, msg = run("diagram", path, "-o", out, "-q")
        verdict = f"diagram rc={rc}"
        if rc == 0:
            crc, cmsg = run("check", out)
            verdict += f" check rc={crc} {cmsg[0][:100] if cmsg else ''}"
            if crc != 0: bad += 1
        else:
            verdict += " " + (msg[-1][:140] if msg else "")
            if rc != 2: bad += 1
        print(f"  {name:32s} {verdict}")
    print(f"engine: {bad} wrong")
    return bad

def recognize_one(graph_path, extra=()):
    out = graph_path + ".rec.json"
    rc, msg = run("recognize", graph_path, "-o", out, *extra)
    rec = json.load(open(out)) if os.path.exists(out) else None
    return rc, msg, rec

def site_error(sites, rec):
    """max position error / extent, max relative weight error (weights normalised to max 1), matched by nearest."""
    xs = [s[0] for s in sites]; ys = [s[1] for s in sites]
    ext = math.hypot(max(xs) - min(xs), max(ys) - min(ys))
    wmax = max(s[2] for s in sites)
    rs = rec.get("sites", [])
    if not rs: return None
    rwmax = max(r["weight"] for r in rs)
    pe = we = 0.0
    for (x, y, w) in sites:
        r = min(rs, key=lambda r: (r["x"] - x) ** 2 + (r["y"] - y) ** 2)
        pe = max(pe, math.hypot(r["x"] - x, r["y"] - y) / ext)
        we = max(we, abs(r["weight"] / rwmax - w / wmax) / (w / wmax))
    return pe, we

def recognize():
    rng = random.Random(5)
    base = [(rng.uniform(0, 1000), rng.uniform(0, 1000), rng.uniform(1, 2)) for _ in range(300)]
    c, s_ = math.cos(0.7), math.sin(0.7)
    variants = {
        "origin": base,
        "near-1e7": [(x + 1e7, y + 1e7, w) for x, y, w in base],
        "rotated": [(c * x - s_ * y, s_ * x + c * y, w) for x, y, w in base],
        "scaled-1e-3": [(x * 1e-3, y * 1e-3, w) for x, y, w in base],
        "scaled-1e5": [(x * 1e5, y * 1e5, w) for x, y, w in base],
    }
    rng2 = random.Random(7)
    for name, s in list(variants.items()) + [(n, s) for n, s in families(rng2) if n.endswith("s1")]:
        path = write_sites("rec-" + name, s)
        g = path[:-4] + ".json"
        rc, _ = run("diagram", path, "-o", g, "-q")
        if rc: print(f"  {name:32s} diagram rc={rc}"); continue
        crc, _ = run("check", g)
        rc, msg, rec = recognize_one(g)
        err = site_error(s, rec) if rec else None
        summary = [l for l in msg if "voronoi" in l.lower() or "mwvd" in l.lower()][:1]
        e = f"pos {err[0]:.1e} w {err[1]:.1e}" if err else "-"
        print(f"  {name:32s} check={crc} recognize rc={rc} {e} {summary[0][:80] if summary else (msg[-1][:80] if msg else '')}")

def labels():
    rng = random.Random(3)
    s = [(rng.uniform(0, 100), rng.uniform(0, 100), rng.uniform(1, 2)) for _ in range(30)]
    path = write_sites("labels", s); g = path[:-4] + ".json"
    run("diagram", path, "-o", g, "-q")
    d = json.load(open(g))
    d["sites"][3], d["sites"][7] = d["sites"][7], d["sites"][3]
    sw = g[:-5] + "-swapped.json"; json.dump(d, open(sw, "w"))
    for p in [g, sw]:
        rc, msg, rec = recognize_one(p)
        print(f"  {os.path.basename(p):24s} rc={rc} input_sites={json.dumps(rec.get('input_sites'))[:160] if rec else None}")

def round_graph(d, digits):
    def r(v):
        return float(f"{v:.{digits}g}") if isinstance(v, float) else v
    for n in d["nodes"]: n["x"], n["y"] = r(n["x"]), r(n["y"])
    for a in d["arcs"]:
        for k in ("circle", "line"):
            if k in a:
                for f in a[k]:
                    if isinstance(a[k][f], float): a[k][f] = r(a[k][f])
    d["sites"] = []
    return d

def rounded():
    rng = random.Random(9)
    for n in [30, 300]:
        s = [(rng.uniform(0, 1000), rng.uniform(0, 1000), rng.uniform(1, 2)) for _ in range(n)]
        path = write_sites(f"round{n}", s); g = path[:-4] + ".json"
        run("diagram", path, "-o", g, "-q")
        for digits in [15, 12, 9, 6]:
            d = round_graph(json.load(open(g)), digits)
            p = g[:-5] + f"-d{digits}.json"; json.dump(d, open(p, "w"))
            for tol in ["1e-7", "1e-4"]:
                rc, msg, rec = recognize_one(p, ("--tolerance", tol))
                err = site_error(s, rec) if rec and rec.get("sites") else None
                e = f"pos {err[0]:.1e} w {err[1]:.1e}" if err else "-"
                print(f"  n={n} digits={digits:2d} tol={tol} rc={rc} {e} {msg[0][:90] if msg else ''}")

wrong = 0
for sec in SECTIONS:
    print(f"== {sec}")
    wrong += globals()[sec]() or 0
sys.exit(1 if wrong else 0)
