#!/usr/bin/env python3
"""Times covmap on hostile inputs (docs/RELIABILITY.md has the figures).

Usage: bench/hostile_inputs.py BUILD_DIR [--json] [--only NAME ...] [--work DIR]

Each case generates its input, runs one covmap command under a time limit, and reports the
whole-process wall time, peak memory (ru_maxrss of the child), exit code and the first line of
the message. It measures; it asserts nothing (tests/cli/safety_test.sh asserts the behaviour).
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile

LIMIT_SECONDS = 900


def write(path, text):
    with open(path, "w") as f:
        f.write(text)
    return path


def deep(n=200_000):
    return "[" * n + "]" * n


def square_grid_map(path, n, cell=10.0, sensors=None):
    """n x n square cells; each its own sensor, or `sensors` distinct sensors in turn."""
    with open(path, "w") as f:
        f.write('{"type":"FeatureCollection","features":[\n')
        for i in range(n):
            for j in range(n):
                k = i * n + j
                x, y = i * cell, j * cell
                name = f"s{k}" if sensors is None else f"s{k % sensors}"
                ring = [[x, y], [x + cell, y], [x + cell, y + cell], [x, y + cell], [x, y]]
                f.write(("" if k == 0 else ",\n") + json.dumps(
                    {"type": "Feature", "properties": {"sensor": name},
                     "geometry": {"type": "Polygon", "coordinates": [ring]}}))
        f.write("]}\n")
    return path


def spiral_polygon(path, n):
    """A simple polygon of n vertices: a thin two-armed spiral (many long, close edges)."""
    import math
    turns = max(2, n // 400)
    inner, outer = [], []
    m = n // 2
    for k in range(m):
        t = turns * 2 * math.pi * k / m
        r = 1.0 + t
        inner.append([r * math.cos(t), r * math.sin(t)])
        outer.append([(r + 0.5) * math.cos(t), (r + 0.5) * math.sin(t)])
    ring = inner + outer[::-1]
    write(path, json.dumps({"format": "covmap.polygon/1", "points": ring}))
    return path


def cases(work, make_map):
    planar = os.path.join(work, "planar")
    geo = os.path.join(work, "geo")
    big = os.path.join(work, "m1e4")
    subprocess.run([make_map, "--random", "6", "--area", "5,5", "--seed", "3", "-o", planar, "-q"], check=True)
    subprocess.run([make_map, "--random", "6", "--area", "5,5", "--seed", "3", "--lonlat", "7.4,46.9", "-o", geo, "-q"],
                   check=True)
    pmap = os.path.join(planar, "map.geojson")
    sites = write(os.path.join(work, "s.csv"), "id,x,y,weight\na,0,0,1\nb,10,0,2\nc,0,10,1.5\nd,10,10,1\n")

    def typo():
        m = json.load(open(pmap))
        m["features"][1]["geometry"]["coordinates"][0][1][1] = 2147483648
        return write(os.path.join(work, "typo.geojson"), json.dumps(m))

    def scaled():
        def s(c):
            return [s(v) for v in c] if isinstance(c[0], list) else [c[0] * 1e150, c[1] * 1e150]
        m = json.load(open(pmap))
        for f in m["features"]:
            f["geometry"]["coordinates"] = s(f["geometry"]["coordinates"])
        return write(os.path.join(work, "huge.geojson"), json.dumps(m))

    def far_sensors():
        s = json.load(open(os.path.join(planar, "sensors.geojson")))
        for f in s["features"][:2]:
            f["geometry"]["coordinates"][0] += 3.0e6
        return write(os.path.join(work, "far.geojson"), json.dumps(s))

    def many_reported():
        rows = ["id,x,y,weight"] + [f"r{k},{(k % 300) * 17.0},{(k // 300) * 17.0},1" for k in range(100_000)]
        return write(os.path.join(work, "many.csv"), "\n".join(rows) + "\n")

    def user_folder():
        d = os.path.join(work, "userdir")
        os.makedirs(d, exist_ok=True)
        write(os.path.join(d, "mydata.txt"), "precious")
        return d

    def ten_thousand():
        if not os.path.exists(big):
            subprocess.run([make_map, "--random", "10000", "--area", "200,200", "--seed", "5", "-o", big, "-q"],
                           check=True)
        return os.path.join(big, "map.geojson")

    o = lambda name: os.path.join(work, "out-" + name)
    return [
        ("deep JSON in map coordinates (200 KB of brackets)",
         lambda: ["audit", write(os.path.join(work, "deep_map.geojson"),
                                 '{"type":"FeatureCollection","features":[{"type":"Feature","properties":{"sensor":"a"},'
                                 '"geometry":{"type":"Polygon","coordinates":' + deep() + '}}]}'), "-o", o("1"), "-q"]),
        ("deep JSON in a crs member",
         lambda: ["audit", write(os.path.join(work, "deep_crs.geojson"),
                                 '{"type":"FeatureCollection","crs":' + deep() + ',"features":[]}'), "-o", o("2"), "-q"]),
        ("deep JSON in a sensors file",
         lambda: ["audit", "--planar", pmap, "--sensors",
                  write(os.path.join(work, "deep_sensors.json"), '{"format":"covmap.sites/1","sites":' + deep() + '}'),
                  "-o", o("3"), "-q"]),
        ("one mistyped coordinate, y = 2147483648 (planar)", lambda: ["audit", "--planar", typo(), "-o", o("4"), "-q"]),
        ("map coordinates scaled by 1e150", lambda: ["audit", "--planar", scaled(), "-o", o("5"), "-q"]),
        ("sites at 1e308", lambda: ["diagram", write(os.path.join(work, "big.csv"),
                                                     "id,x,y,weight\na,0,0,1\nb,1e308,0,2\nc,0,1e308,1.5\n"),
                                    "-o", o("6.json")]),
        ("clip polygon, 30 000 vertices", lambda: ["diagram", sites, "-o", o("7.json"), "-q", "--clip",
                                                   spiral_polygon(os.path.join(work, "clip3e4.json"), 30_000)]),
        ("clip polygon, 10^6 vertices", lambda: ["diagram", sites, "-o", o("8.json"), "-q", "--clip",
                                                 spiral_polygon(os.path.join(work, "clip1e6.json"), 1_000_000)]),
        ("check --probes 2000000000", lambda: ["check", "--probes", "2000000000", write(os.path.join(work, "d.json"), "{}")]),
        ("10^6 tiny features, one sensor each",
         lambda: ["audit", "--planar", square_grid_map(os.path.join(work, "tiny.geojson"), 1000), "-o", o("9"), "-q"]),
        ("10^5 reported sensors on a 6-sensor map",
         lambda: ["audit", "--planar", pmap, "--sensors", many_reported(), "-o", o("10"), "-q", "--force"]),
        ("a lon/lat map given --planar", lambda: ["audit", "--planar", os.path.join(geo, "map.geojson"), "-o", o("11"), "-q"]),
        ("2 reported sensors 3000 km outside the map",
         lambda: ["audit", "--planar", pmap, "--sensors", far_sensors(), "--alpha", "3.5", "-o", o("12"), "-q"]),
        ("--alpha 0", lambda: ["audit", "--planar", pmap, "--alpha", "0", "-o", o("13")]),
        ("-o into a folder holding the user's file", lambda: ["audit", "--planar", pmap, "-o", user_folder(), "-q"]),
        ("reference: a legitimate 10^4-sensor map (generated)",
         lambda: ["audit", "--planar", ten_thousand(), "-o", o("14"), "-q"]),
    ]


def run(covmap, args, work):
    """Whole-process wall time and peak memory as /usr/bin/time reports them."""
    stats = os.path.join(work, "time.txt")
    try:
        p = subprocess.run(["/usr/bin/time", "-f", "%e %M", "-o", stats, covmap] + args, capture_output=True,
                           text=True, timeout=LIMIT_SECONDS)
        code, text = p.returncode, (p.stderr or p.stdout)
        seconds, kb = open(stats).read().split()[-2:]
        seconds, mb = float(seconds), int(kb) / 1024
    except subprocess.TimeoutExpired:
        code, text, seconds, mb = "timeout", "", LIMIT_SECONDS, None
    lines = [line for line in text.strip().splitlines() if not line.startswith("Command exited")]
    return {"seconds": seconds, "max_rss_mb": round(mb, 1) if mb else None, "exit": code,
            "message": lines[0].replace(work + "/", "")[:160] if lines else ""}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("build")
    ap.add_argument("--json", action="store_true")
    ap.add_argument("--only", nargs="*")
    ap.add_argument("--work")
    a = ap.parse_args()
    covmap = os.path.join(a.build, "cli", "covmap")
    make_map = os.path.join(a.build, "tools", "mapgen", "covmap-make-map")
    work = a.work or tempfile.mkdtemp(prefix="covmap-hostile-")
    results = []
    for name, make_args in cases(work, make_map):
        if a.only and not any(o in name for o in a.only):
            continue
        args = make_args()
        r = run(covmap, args, work)
        r["case"] = name
        results.append(r)
        if not a.json:
            rss = f"{r['max_rss_mb']:.0f} MB" if r["max_rss_mb"] else "-"
            print(f"| {name} | {r['seconds']:.2f} s | {rss} | {r['exit']} | {r['message']} |", flush=True)
    if a.json:
        json.dump({"command": " ".join(sys.argv), "results": results}, sys.stdout, indent=1)
        print()
    if not a.work:
        shutil.rmtree(work, ignore_errors=True)


if __name__ == "__main__":
    main()
