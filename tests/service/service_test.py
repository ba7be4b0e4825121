#!/usr/bin/env python3
"""`covmap serve` driven over real HTTP: a server on a free loopback port, Python's own
HTTP client, the bundled maps.

Usage: service_test.py path/to/covmap path/to/datasets WORKDIR [part]
Parts (ctest registers them apart; no part: all): api, errors, concurrent, restart, limits.

  api         the Bern audit through the API gives the same report.json verdicts as the CLI;
              the job's status, progress and files; the synchronous /v1/diagram answers as
              `covmap diagram`; every path of /openapi.json is routed (not "no route")
  errors      no map part, invalid GeoJSON, wrong JSON options, an unknown option, unknown and
              path-traversing job ids, an oversized upload, a wrong method: the right status, the
              JSON error shape, and no job or file left behind
  concurrent  20 jobs submitted at once all finish, each with its own correct report
  restart     a server killed with SIGKILL mid-job and restarted serves every finished job's files
              and runs the interrupted job again (attempts 2), leaving no orphan audit process
  limits      an audit over --job-cpu-seconds is stopped and failed with the reason; the next job runs;
              a full queue (--queue) answers 503 and stores nothing
Exits 1 listing every failure.
"""
import json
import os
import re
import signal
import subprocess
import sys
import threading
import time
import urllib.error
import urllib.request
import uuid
from pathlib import Path

FAILURES = []


def fail(message):
    FAILURES.append(message)
    print("FAIL:", message)


def check(condition, message):
    if not condition:
        fail(message)
    return condition


class Server:
    """covmap serve on a free port, its data folder given."""

    def __init__(self, covmap, data, *extra):
        self.proc = subprocess.Popen([str(covmap), "serve", "--port", "0", "--data", str(data), *map(str, extra)],
                                     stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
        line = self.proc.stdout.readline()
        match = re.search(r"http://([^/]+)/", line)
        if not match:
            raise RuntimeError(f"covmap serve did not start: {line!r} {self.proc.stderr.read()}")
        self.base = f"http://{match.group(1)}"
        self.first_line = line

    # The waits are generous: a stop kills the running audits and closes the store, quick on a quiet
    # machine but far slower on a loaded one.
    def stop(self):
        self.proc.send_signal(signal.SIGTERM)
        self.proc.wait(timeout=120)

    def kill(self):
        self.proc.send_signal(signal.SIGKILL)
        self.proc.wait(timeout=120)


def request(server, method, path, body=None, headers=None):
    req = urllib.request.Request(server.base + path, data=body, method=method, headers=headers or {})
    try:
        with urllib.request.urlopen(req, timeout=120) as res:
            return res.status, res.headers, res.read()
    except urllib.error.HTTPError as e:
        return e.code, e.headers, e.read()
    except (ConnectionError, urllib.error.URLError) as e:
        # A server may answer an oversized body before reading it and close the connection; the
        # client then sees the reset, not the answer.
        return 0, {}, json.dumps({"error": {"code": "connection", "message": str(e), "where": ""}}).encode()


def get_json(server, path):
    status, _, body = request(server, "GET", path)
    return status, json.loads(body)


def multipart(parts):
    """parts: [(name, filename or None, bytes)] -> (body, content type)."""
    boundary = uuid.uuid4().hex
    out = bytearray()
    for name, filename, content in parts:
        out += f"--{boundary}\r\n".encode()
        disposition = f'form-data; name="{name}"' + (f'; filename="{filename}"' if filename else "")
        out += f"Content-Disposition: {disposition}\r\n\r\n".encode()
        out += content + b"\r\n"
    out += f"--{boundary}--\r\n".encode()
    return bytes(out), f"multipart/form-data; boundary={boundary}"


def submit(server, map_path, sensors_path=None, options=None, map_bytes=None):
    parts = [("map", Path(map_path).name, map_bytes if map_bytes is not None else Path(map_path).read_bytes())]
    if sensors_path:
        parts.append(("sensors", Path(sensors_path).name, Path(sensors_path).read_bytes()))
    if options is not None:
        parts.append(("options", None, json.dumps(options).encode() if not isinstance(options, bytes) else options))
    body, content_type = multipart(parts)
    status, headers, answer = request(server, "POST", "/v1/audits", body, {"Content-Type": content_type})
    return status, headers, json.loads(answer)


def wait_done(server, job_id, timeout=300):
    deadline = time.time() + timeout
    while time.time() < deadline:
        _, job = get_json(server, f"/v1/audits/{job_id}")
        if job["status"] in ("done", "failed", "cancelled"):
            return job
        time.sleep(0.2)
    raise RuntimeError(f"job {job_id} did not finish in {timeout} s")


def verdicts(report):
    return {s["id"]: s["verdict"] for s in report["sensors"]}


def cli_report(covmap, work, name, map_path, sensors_path, *extra):
    out = work / f"cli_{name}"
    subprocess.run([str(covmap), "audit", str(map_path), "--sensors", str(sensors_path), "--alpha", "3.5", "-q",
                    "-o", str(out), *extra], check=True, stdout=subprocess.DEVNULL)
    return json.loads((out / "report.json").read_text())


def job_folders(data):
    jobs = data / "jobs"
    return sorted(p.name for p in jobs.iterdir()) if jobs.exists() else []


def part_api(covmap, datasets, work):
    bern = datasets / "maps" / "bern"
    data = work / "data_api"
    server = Server(covmap, data)
    try:
        status, headers, job = submit(server, bern / "map.geojson", bern / "sensors.geojson", {"alpha": 3.5})
        check(status == 202 and job["status"] == "queued", f"api: submit answered {status} {job}")
        check(headers.get("Location") == f"/v1/audits/{job['id']}", f"api: Location header {headers.get('Location')}")
        seen = set()
        deadline = time.time() + 300
        while time.time() < deadline:
            _, now = get_json(server, f"/v1/audits/{job['id']}")
            seen.add(now["status"])
            check(0.0 <= now["progress"] <= 1.0, f"api: progress {now['progress']}")
            if now["status"] == "done":
                break
            time.sleep(0.1)
        check(now["status"] == "done", f"api: job ended {now['status']}: {now.get('error')}")
        check("running" in seen or "queued" in seen, f"api: statuses seen {seen}")
        check(now["summary"] is not None, f"api: no summary in the finished job: {now}")
        expected = cli_report(covmap, work, "bern", bern / "map.geojson", bern / "sensors.geojson")
        status, _, body = request(server, "GET", f"/v1/audits/{job['id']}/report.json")
        check(status == 200, f"api: report.json answered {status}")
        got = json.loads(body)
        check(verdicts(got) == verdicts(expected), "api: the service's verdicts differ from the CLI's")
        check(got["summary"] == expected["summary"], "api: the service's summary differs from the CLI's")
        for name in ("report.html", "sensors.geojson", "shifts.geojson", "diagram.geojson"):
            status, headers, body = request(server, "GET", f"/v1/audits/{job['id']}/{name}")
            check(status == 200 and len(body) > 100, f"api: {name} answered {status}, {len(body)} bytes")
        status, listing = get_json(server, "/v1/audits")
        check(status == 200 and listing["jobs"][0]["id"] == job["id"], "api: the job is not first in the list")
        # A batch: several map parts, one job each, each with the summary `covmap audit` gives.
        swiss = datasets / "maps" / "switzerland"
        body, content_type = multipart([("map", "bern.geojson", (bern / "map.geojson").read_bytes()),
                                        ("map", "switzerland.geojson", (swiss / "map.geojson").read_bytes()),
                                        ("options", None, b'{"alpha": 3.5}')])
        status, _, answer = request(server, "POST", "/v1/audits", body, {"Content-Type": content_type})
        batch = json.loads(answer).get("jobs", [])
        check(status == 202 and len(batch) == 2, f"api: a batch of two maps answered {status} with {len(batch)} jobs")
        for entry, source in zip(batch, (bern, swiss)):
            finished = wait_done(server, entry["id"])
            out = work / f"cli_batch_{source.name}"
            subprocess.run([str(covmap), "audit", str(source / "map.geojson"), "--alpha", "3.5", "-q", "-o", str(out)],
                           check=True, stdout=subprocess.DEVNULL)
            expected = json.loads((out / "report.json").read_text())["summary"]
            check(finished["status"] == "done" and finished["summary"] == expected,
                  f"api: the batch's {source.name} job: {finished['status']}, summary {finished['summary']} vs {expected}")
        # Synchronous: /v1/diagram answers as `covmap diagram` does.
        sites = work / "sites.csv"
        sites.write_text("id,x,y,weight\na,0,0,1\nb,10,0,2\nc,3,8,1.5\nd,7,5,1\n")
        subprocess.run([str(covmap), "diagram", str(sites), "-o", str(work / "diagram.json"), "-q"], check=True)
        status, _, body = request(server, "POST", "/v1/diagram", sites.read_bytes(), {"Content-Type": "text/csv"})
        check(status == 200 and json.loads(body) == json.loads((work / "diagram.json").read_text()),
              f"api: /v1/diagram differs from covmap diagram ({status})")
        graph = body
        status, _, body = request(server, "POST", "/v1/check", graph, {"Content-Type": "application/json"})
        check(status == 200 and json.loads(body)["ok"] is True, f"api: /v1/check of the engine's diagram: {body[:200]}")
        # /v1/recognize answers as `covmap recognize -o` writes; /v1/compare finds a graph equal to itself.
        subprocess.run([str(covmap), "recognize", str(work / "diagram.json"), "-o", str(work / "recon.json")],
                       check=True, stdout=subprocess.DEVNULL)
        status, _, body = request(server, "POST", "/v1/recognize", graph, {"Content-Type": "application/json"})
        check(status == 200 and json.loads(body) == json.loads((work / "recon.json").read_text()),
              f"api: /v1/recognize differs from covmap recognize ({status})")
        pair = json.dumps({"a": json.loads(graph), "b": json.loads(graph)}).encode()
        status, _, body = request(server, "POST", "/v1/compare", pair, {"Content-Type": "application/json"})
        check(status == 200 and json.loads(body)["equal"] is True, f"api: /v1/compare of a graph with itself: {body[:200]}")
        # Every path of the API document is routed.
        status, _, body = request(server, "GET", "/openapi.json")
        document = json.loads(body)
        for path, operations in document["paths"].items():
            concrete = path.replace("{id}", job["id"]).replace("{file}", "report.json")
            for method in operations:
                if method == "parameters":
                    continue
                if method == "delete":
                    continue  # exercised below and in the errors part; deleting here would lose the job
                status, _, answer = request(server, method.upper(), concrete, b"{}" if method == "post" else None,
                                            {"Content-Type": "application/json"} if method == "post" else {})
                routed = not (status == 404 and b"no route" in answer)
                check(routed, f"api: {method.upper()} {path} from openapi.json is not routed")
        status, _, answer = request(server, "DELETE", f"/v1/audits/{job['id']}")
        check(status == 200 and json.loads(answer).get("deleted") is True, f"api: delete answered {status} {answer[:200]}")
        check(job["id"] not in job_folders(data), "api: the deleted job's folder is still there")
        status, _, _ = request(server, "GET", f"/v1/audits/{job['id']}")
        check(status == 404, f"api: a deleted job answers {status}")
    finally:
        server.stop()


def expect_error(server, what, answer, status, want_status, where=None):
    try:
        error = json.loads(answer)["error"]
    except (ValueError, KeyError, TypeError):
        fail(f"errors: {what}: not the JSON error shape: {answer[:200]!r}")
        return
    check(status == want_status, f"errors: {what}: status {status}, want {want_status} ({error})")
    check(set(error) == {"code", "message", "where"}, f"errors: {what}: error members {set(error)}")
    if where is not None:
        check(error["where"].startswith(where), f"errors: {what}: where {error['where']!r}, want {where!r}...")


def part_errors(covmap, datasets, work):
    bern = datasets / "maps" / "bern"
    data = work / "data_errors"
    server = Server(covmap, data, "--max-upload-mb", 1)
    try:
        body, content_type = multipart([("sensors", "s.geojson", (bern / "sensors.geojson").read_bytes())])
        status, _, answer = request(server, "POST", "/v1/audits", body, {"Content-Type": content_type})
        expect_error(server, "no map part", answer, status, 400, "map")
        status, _, answer = submit(server, "map.geojson", map_bytes=b'{"type":"FeatureCollection","features":[{]}')
        expect_error(server, "invalid GeoJSON", json.dumps(answer).encode(), status, 400, "map")
        broken = json.loads((bern / "map.geojson").read_text())
        broken["features"][3]["geometry"]["coordinates"][0].pop()  # ring no longer closed
        status, _, answer = submit(server, "map.geojson", map_bytes=json.dumps(broken).encode())
        expect_error(server, "a ring not closed", json.dumps(answer).encode(), status, 400, "map: features[3]")
        status, _, answer = submit(server, bern / "map.geojson", options=b"{alpha: 3}")
        expect_error(server, "options not JSON", json.dumps(answer).encode(), status, 400, "options")
        status, _, answer = submit(server, bern / "map.geojson", options={"alpha": "high"})
        expect_error(server, "alpha not a number", json.dumps(answer).encode(), status, 400, "options.alpha")
        status, _, answer = submit(server, bern / "map.geojson", options={"colour": "red"})
        expect_error(server, "unknown option", json.dumps(answer).encode(), status, 400, "options.colour")
        status, _, answer = submit(server, bern / "map.geojson", bern / "sensors.geojson", {"planar": True})
        expect_error(server, "lon/lat map given planar", json.dumps(answer).encode(), status, 400, "map")
        for job_id in ("0123456789abcdef0123456789abcdef", "..%2F..%2Fjobs.sqlite", "../../etc/passwd", "ABC"):
            status, _, answer = request(server, "GET", f"/v1/audits/{job_id}")
            expect_error(server, f"job id {job_id}", answer, status, 404)
            status, _, answer = request(server, "GET", f"/v1/audits/{job_id}/report.json")
            expect_error(server, f"job id {job_id} file", answer, status, 404)
        body, content_type = multipart([("map", "bern.geojson", (bern / "map.geojson").read_bytes()),
                                        ("map", "broken.geojson", b'{"type":"FeatureCollection","features":[{]}')])
        status, _, answer = request(server, "POST", "/v1/audits", body, {"Content-Type": content_type})
        expect_error(server, "a batch with a broken map", answer, status, 400, "map[1] (broken.geojson)")
        big = b"x" * (2 << 20)
        status, _, answer = submit(server, "map.geojson", map_bytes=big)
        expect_error(server, "upload over --max-upload-mb", json.dumps(answer).encode() if isinstance(answer, dict) else answer,
                     status, 413)
        status, _, answer = request(server, "PUT", "/v1/audits", b"", {})
        check(status in (404, 405), f"errors: PUT answered {status}")
        status, _, answer = request(server, "GET", "/v1/nothing")
        expect_error(server, "unknown route", answer, status, 404)
        status, _, answer = request(server, "POST", "/v1/diagram", b"id,x,y,weight\na,0,0,-1\n", {"Content-Type": "text/csv"})
        expect_error(server, "diagram of a bad site", answer, status, 400, "sites")
        # A second server on the same data folder, or on a port in use: refused at start, exit 2.
        second = subprocess.run([str(covmap), "serve", "--port", "0", "--data", str(data)], capture_output=True,
                                text=True, timeout=30)
        check(second.returncode == 2 and "another covmap serve uses the data folder" in second.stderr,
              f"errors: a second server on the data folder: exit {second.returncode}, {second.stderr.strip()}")
        port = server.base.rsplit(":", 1)[1]
        taken = subprocess.run([str(covmap), "serve", "--port", port, "--data", str(work / "data_other")],
                               capture_output=True, text=True, timeout=30)
        check(taken.returncode == 2 and "cannot listen" in taken.stderr,
              f"errors: a port in use: exit {taken.returncode}, {taken.stderr.strip()}")
        check(job_folders(data) == [], f"errors: refused requests left job folders {job_folders(data)}")
        _, listing = get_json(server, "/v1/audits")
        check(listing["jobs"] == [], f"errors: refused requests left jobs {[j['id'] for j in listing['jobs']]}")
    finally:
        server.stop()


def part_concurrent(covmap, datasets, work):
    bern = datasets / "maps" / "bern"
    data = work / "data_concurrent"
    server = Server(covmap, data, "--workers", 2)
    try:
        ids, lock = [], threading.Lock()

        def one():
            status, _, job = submit(server, bern / "map.geojson", bern / "sensors.geojson", {"alpha": 3.5})
            with lock:
                ids.append((status, job.get("id")))

        threads = [threading.Thread(target=one) for _ in range(20)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        check(all(status == 202 for status, _ in ids), f"concurrent: statuses {[s for s, _ in ids]}")
        expected = verdicts(cli_report(covmap, work, "bern_c", bern / "map.geojson", bern / "sensors.geojson"))
        for _, job_id in ids:
            job = wait_done(server, job_id, timeout=900)
            if not check(job["status"] == "done", f"concurrent: job {job_id} ended {job['status']}: {job.get('error')}"):
                continue
            _, _, body = request(server, "GET", f"/v1/audits/{job_id}/report.json")
            check(verdicts(json.loads(body)) == expected, f"concurrent: job {job_id}'s verdicts differ from the CLI's")
        print(f"  concurrent: {len(ids)} jobs done")
    finally:
        server.stop()


def heavy_map(covmap, work):
    """A planar map whose audit takes seconds on any machine, however fast the audit gets: 3 000
    generated sensors, ~6 s of CPU (the bundled Swiss map once took 2 s, now about 0.6 s)."""
    make_map = Path(os.environ.get("COVMAP_MAKE_MAP", covmap.parent.parent / "tools" / "mapgen" / "covmap-make-map"))
    generated = work / "heavy_map"
    if not (generated / "map.geojson").exists():
        subprocess.run([str(make_map), "--random", "3000", "--area", "110,110", "--weight-ratio", "3", "--bin", "100",
                        "--seed", "1", "-q", "-o", str(generated)], check=True)
    return generated


def part_limits(covmap, datasets, work):
    """An audit over its CPU limit is stopped and its job failed with the reason; the server and
    the next job are unaffected."""
    bern = datasets / "maps" / "bern"
    generated = heavy_map(covmap, work)
    data = work / "data_limits"
    server = Server(covmap, data, "--workers", 1, "--job-cpu-seconds", 1)
    try:
        _, _, heavy = submit(server, generated / "map.geojson", generated / "sensors.geojson", {"alpha": 3.5, "planar": True})
        job = wait_done(server, heavy["id"])
        check(job["status"] == "failed" and job["error"]["code"] == "resource_limit" and "CPU" in job["error"]["message"],
              f"limits: the audit over its CPU limit ended {job['status']} {job.get('error')}")
        status, _, answer = request(server, "GET", f"/v1/audits/{heavy['id']}/report.json")
        check(status == 404 and json.loads(answer)["error"]["code"] == "not_ready",
              f"limits: a failed job's report answered {status}")
        _, _, light = submit(server, bern / "map.geojson", None, {"alpha": 3.5})
        job = wait_done(server, light["id"])
        # Bern alone takes well under the CPU limit.
        check(job["status"] == "done", f"limits: the next job ended {job['status']} {job.get('error')}")
        print(f"  limits: over the limit -> {json.dumps(wait_done(server, heavy['id'])['error'])[:160]}")
    finally:
        server.stop()
    # A full queue: one job running, one waiting (--queue 1), the third refused with 503.
    server = Server(covmap, work / "data_queue", "--workers", 1, "--queue", 1)
    try:
        _, _, running = submit(server, generated / "map.geojson", None, {"alpha": 3.5, "planar": True})
        deadline = time.time() + 60
        while time.time() < deadline and get_json(server, f"/v1/audits/{running['id']}")[1]["status"] == "queued":
            time.sleep(0.05)
        status, _, _ = submit(server, bern / "map.geojson", None, {"alpha": 3.5})
        check(status == 202, f"limits: the job that fills the queue answered {status}")
        status, _, answer = submit(server, bern / "map.geojson", None, {"alpha": 3.5})
        check(status == 503 and answer["error"]["code"] == "queue_full", f"limits: a full queue answered {status} {answer}")
        _, listing = get_json(server, "/v1/audits")
        check(len(listing["jobs"]) == 2, f"limits: the refused job left {len(listing['jobs']) - 2} job(s)")
    finally:
        server.stop()


def audit_processes(data):
    """covmap audit processes working in this data folder (orphans, if any), read from /proc."""
    found = []
    for entry in Path("/proc").iterdir():
        if not entry.name.isdigit():
            continue
        try:
            words = (entry / "cmdline").read_bytes().split(b"\0")
        except OSError:
            continue
        text = [w.decode(errors="replace") for w in words if w]
        if len(text) > 1 and text[1] in ("audit", "audit-job") and any(str(data) in w for w in text):
            found.append(" ".join(text))
    return found


def part_restart(covmap, datasets, work):
    bern = datasets / "maps" / "bern"
    data = work / "data_restart"
    server = Server(covmap, data, "--workers", 1)
    _, _, first = submit(server, bern / "map.geojson", bern / "sensors.geojson", {"alpha": 3.5})
    check(wait_done(server, first["id"])["status"] == "done", "restart: the first job did not finish")
    heavy = heavy_map(covmap, work)
    _, _, long_job = submit(server, heavy / "map.geojson", heavy / "sensors.geojson", {"alpha": 3.5, "planar": True})
    deadline = time.time() + 60
    while time.time() < deadline and get_json(server, f"/v1/audits/{long_job['id']}")[1]["status"] != "running":
        time.sleep(0.05)
    # Into the audit (it takes several seconds), not past it.
    time.sleep(0.5)
    check(get_json(server, f"/v1/audits/{long_job['id']}")[1]["status"] == "running", "restart: the long job is not running")
    server.kill()
    time.sleep(0.5)
    check(audit_processes(data) == [], f"restart: orphan audits after SIGKILL: {audit_processes(data)}")
    server = Server(covmap, data, "--workers", 1)
    try:
        check("requeued" in server.first_line, f"restart: the start message does not say what was recovered: {server.first_line!r}")
        status, _, body = request(server, "GET", f"/v1/audits/{first['id']}/report.json")
        check(status == 200 and json.loads(body)["sensors"], f"restart: the finished job's report answered {status}")
        _, job = get_json(server, f"/v1/audits/{long_job['id']}")
        check(job["status"] in ("queued", "running"), f"restart: the interrupted job is {job['status']}")
        job = wait_done(server, long_job["id"], timeout=600)
        check(job["status"] == "done" and job["attempts"] == 2,
              f"restart: the interrupted job ended {job['status']} after {job['attempts']} attempts")
        print(f"  restart: {server.first_line.strip()}; the interrupted job ended {job['status']} after "
              f"{job['attempts']} attempts")
    finally:
        server.stop()


def main():
    covmap, datasets, work = Path(sys.argv[1]).resolve(), Path(sys.argv[2]).resolve(), Path(sys.argv[3]).resolve()
    parts = sys.argv[4:] or ["api", "errors", "concurrent", "restart", "limits"]
    subprocess.run(["rm", "-rf", str(work)], check=True)
    work.mkdir(parents=True)
    for part in parts:
        print(f"{part}:")
        globals()[f"part_{part}"](covmap, datasets, work)
    return 1 if FAILURES else 0


if __name__ == "__main__":
    sys.exit(main())
