#!/usr/bin/env python3
"""covmap audit on the bundled Bern map converted by GDAL's own tools into the formats and CRSs
planners export, against the audit of the GeoJSON original.

Usage: gis_formats_test.py path/to/covmap path/to/datasets WORKDIR

The oracle is the audit of datasets/maps/bern as bundled (WGS84 GeoJSON map and sensors). GDAL
(ogr2ogr, gdal_rasterize; Debian's gdal-bin) converts the same data into GeoPackage, Shapefile,
FlatGeobuf, GeoJSON in EPSG:2056 (LV95, with its legacy "crs" member), GeoPackage sensors in
EPSG:2056, CSV sensors with LV95 x/y columns (--sensor-crs) and GeoTIFF best-server rasters in
EPSG:2056 (values = sensor ids; values = feature numbers with a CSV table; the same with a raster
attribute table). Asserted:
  - vector conversions: every sensor's verdict equals the original's, and its reconstructed
    position lies within POSITION_TOLERANCE_M of the original's (the data are the same; only the
    route through GDAL, PROJ and another plane differs);
  - rasters: the same verdicts, and for the consistent sensors reconstructed positions within the
    map's own resolution (its bin size, 200 m: the LV95 raster re-samples a staircase drawn on
    another grid, moving boundaries by up to a bin's diagonal fraction) and, in the median, within
    one raster pixel (RASTER_M);
  - --format gpkg: audit.gpkg has the tables sensors (Point), shifts (LineString) and diagram
    (MultiPolygon) in the map's CRS (EPSG:2056 for the LV95 map, EPSG:4326 for the lon/lat one),
    every diagram geometry valid (GEOS, through GDAL's SQL), and as many sensors as report.json.
Exits 1 listing every failure.
"""
import json
import math
import shutil
import subprocess
import sys
from pathlib import Path

POSITION_TOLERANCE_M = 0.5
RASTER_M = 50.0


def run(args, check=True):
    p = subprocess.run([str(a) for a in args], capture_output=True, text=True)
    if check and p.returncode != 0:
        raise RuntimeError(f"{' '.join(map(str, args))} exited {p.returncode}:\n{p.stdout}\n{p.stderr}")
    return p


def audit(covmap, work, name, map_path, sensors, *extra):
    out = work / f"out_{name}"
    run([covmap, "audit", map_path, "--sensors", sensors, "--alpha", "3.5", "-q", "-o", out, *extra])
    return out


def sensors_of(out):
    report = json.loads((out / "report.json").read_text())
    return {s["id"]: s for s in report["sensors"]}


def metres_apart(a, b):
    """Distance of two WGS84 positions, on a sphere (good to 0.5 % over a few km)."""
    lat = math.radians((a["lat"] + b["lat"]) / 2)
    dx = math.radians(a["lon"] - b["lon"]) * math.cos(lat) * 6371008.8
    dy = math.radians(a["lat"] - b["lat"]) * 6371008.8
    return math.hypot(dx, dy)


def compare(label, reference, got, tolerance_m, only_consistent, failures, median_m=None):
    if set(reference) != set(got):
        failures.append(f"{label}: sensors differ: {sorted(set(reference) ^ set(got))[:5]}")
        return
    worst = 0.0
    distances = []
    for sid, ref in reference.items():
        s = got[sid]
        if s["verdict"] != ref["verdict"]:
            failures.append(f"{label}: sensor {sid}: verdict {s['verdict']}, the GeoJSON original gives {ref['verdict']}")
        if not ref["in_map"] or (only_consistent and ref["verdict"] != "consistent"):
            continue
        d = metres_apart(ref, s)
        worst = max(worst, d)
        distances.append(d)
        if d > tolerance_m:
            failures.append(f"{label}: sensor {sid}: reconstructed {d:.2f} m from the original's (tolerance {tolerance_m} m)")
    distances.sort()
    median = distances[len(distances) // 2] if distances else 0.0
    if median_m is not None and median > median_m:
        failures.append(f"{label}: median distance {median:.1f} m from the original's positions (tolerance {median_m} m)")
    print(f"  {label}: {len(got)} sensors, verdicts as the original, positions within {worst:.3f} m (median {median:.3f} m)")


def check_geopackage(label, out, epsg, failures):
    gpkg = out / "audit.gpkg"
    if not gpkg.exists():
        failures.append(f"{label}: no audit.gpkg")
        return
    for table, geometry in (("sensors", "Point"), ("shifts", "Line String"), ("diagram", "Multi Polygon")):
        info = run(["ogrinfo", "-so", gpkg, table]).stdout
        if f"Geometry: {geometry}\n" not in info:
            failures.append(f"{label}: table {table} is not of geometry {geometry}")
        if f'ID["EPSG",{epsg}]' not in info:
            failures.append(f"{label}: table {table} does not carry EPSG:{epsg}")
    valid = run(["ogrinfo", "-q", gpkg, "-sql", "SELECT COUNT(*) AS n, SUM(ST_IsValid(geom)) AS ok FROM diagram"]).stdout
    n = ok = None
    for line in valid.splitlines():
        if line.strip().startswith("n (Integer)"):
            n = int(line.split("=")[1])
        if line.strip().startswith("ok (Integer)"):
            ok = int(line.split("=")[1])
    if n is None or n == 0 or n != ok:
        failures.append(f"{label}: diagram geometries valid: {ok} of {n}")
    count = run(["ogrinfo", "-so", gpkg, "sensors"]).stdout
    expected = len(json.loads((out / "report.json").read_text())["sensors"])
    if f"Feature Count: {expected}\n" not in count:
        failures.append(f"{label}: the sensors table does not hold the report's {expected} sensors")
    print(f"  {label}: audit.gpkg in EPSG:{epsg}, {n} valid diagram polygons")


def raster_attribute_table(path, rows):
    """A GDAL PAM sidecar holding a raster attribute table: value (MinMax usage) -> sensor."""
    xml = ['<PAMDataset><PAMRasterBand band="1"><GDALRasterAttributeTable tableType="thematic">',
           '<FieldDefn index="0"><Name>value</Name><Type>0</Type><Usage>5</Usage></FieldDefn>',
           '<FieldDefn index="1"><Name>sensor</Name><Type>2</Type><Usage>0</Usage></FieldDefn>']
    for i, (value, sensor) in enumerate(rows):
        xml.append(f'<Row index="{i}"><F>{value}</F><F>{sensor}</F></Row>')
    xml.append("</GDALRasterAttributeTable></PAMRasterBand></PAMDataset>")
    Path(str(path) + ".aux.xml").write_text("\n".join(xml))


def main():
    covmap, datasets, work = Path(sys.argv[1]), Path(sys.argv[2]), Path(sys.argv[3])
    for tool in ("ogr2ogr", "gdal_rasterize", "ogrinfo"):
        if not shutil.which(tool):
            print(f"FAIL: {tool} not found: install gdal-bin (scripts/setup-debian.sh)")
            return 1
    shutil.rmtree(work, ignore_errors=True)
    work.mkdir(parents=True)
    bern = datasets / "maps" / "bern"
    map_json, sensors_json = bern / "map.geojson", bern / "sensors.geojson"
    failures = []

    reference_out = audit(covmap, work, "reference", map_json, sensors_json)
    reference = sensors_of(reference_out)
    resolution = json.loads((reference_out / "report.json").read_text())["bin_size_m"]
    print(f"reference: {len(reference)} sensors, the map's bins {resolution:.0f} m")

    conversions = {
        "gpkg": (["-f", "GPKG", "-nln", "cells"], "map.gpkg"),
        "shapefile": (["-f", "ESRI Shapefile"], "map.shp"),
        # Without the spatial index FlatGeobuf keeps the features in file order. (With it, they come
        # back in Hilbert order, and the refinement lands a few metres away, well within the
        # positions' σ: the audit's start depends on the order of the cells.)
        "flatgeobuf": (["-f", "FlatGeobuf", "-lco", "SPATIAL_INDEX=NO"], "map.fgb"),
        "gpkg_lv95": (["-f", "GPKG", "-t_srs", "EPSG:2056", "-nln", "cells"], "map_lv95.gpkg"),
        "geojson_lv95": (["-f", "GeoJSON", "-lco", "RFC7946=NO", "-t_srs", "EPSG:2056"], "map_lv95.geojson"),
    }
    for name, (args, file) in conversions.items():
        run(["ogr2ogr", *args, work / file, map_json])
        compare(name, reference, sensors_of(audit(covmap, work, name, work / file, sensors_json)),
                POSITION_TOLERANCE_M, False, failures)

    # Sensors in LV95 too: a GeoPackage layer, and a semicolon CSV with x/y columns.
    run(["ogr2ogr", "-f", "GPKG", "-t_srs", "EPSG:2056", work / "sensors_lv95.gpkg", sensors_json])
    compare("gpkg_lv95 + sensors gpkg_lv95", reference,
            sensors_of(audit(covmap, work, "s_gpkg", work / "map_lv95.gpkg", work / "sensors_lv95.gpkg")),
            POSITION_TOLERANCE_M, False, failures)
    run(["ogr2ogr", "-f", "CSV", "-t_srs", "EPSG:2056", "-lco", "GEOMETRY=AS_XY", "-lco", "SEPARATOR=SEMICOLON",
         work / "sensors_lv95.csv", sensors_json])
    csv = (work / "sensors_lv95.csv").read_text().splitlines()
    csv[0] = csv[0].replace('"', "").replace("X;Y", "x;y")
    (work / "sensors_lv95.csv").write_text("\n".join(csv) + "\n")
    compare("geojson map + csv sensors in LV95 (--sensor-crs)", reference,
            sensors_of(audit(covmap, work, "s_csv", map_json, work / "sensors_lv95.csv", "--sensor-crs", "EPSG:2056")),
            POSITION_TOLERANCE_M, False, failures)

    # Best-server rasters in LV95.
    run(["gdal_rasterize", "-q", "-a", "sensor", "-tr", RASTER_M, RASTER_M, "-ot", "Int32", "-a_nodata", "0",
         work / "map_lv95.gpkg", work / "ids.tif"])
    compare("raster (values are sensor ids)", reference, sensors_of(audit(covmap, work, "ids", work / "ids.tif", sensors_json)),
            resolution, True, failures, RASTER_M)
    run(["gdal_rasterize", "-q", "-a", "v", "-sql", "SELECT fid * 1 AS v, geom FROM cells", "-tr", RASTER_M, RASTER_M,
         "-ot", "Int16", "-a_nodata", "0", work / "map_lv95.gpkg", work / "numbers.tif"])
    ids = [f["properties"]["sensor"] for f in json.loads(map_json.read_text())["features"]]
    table = work / "table.csv"
    table.write_text("value,sensor\n" + "".join(f"{i + 1},{sid}\n" for i, sid in enumerate(ids)))
    compare("raster + --raster-table", reference,
            sensors_of(audit(covmap, work, "table", work / "numbers.tif", sensors_json, "--raster-table", table)),
            resolution, True, failures, RASTER_M)
    shutil.copy(work / "numbers.tif", work / "rat.tif")
    raster_attribute_table(work / "rat.tif", [(i + 1, sid) for i, sid in enumerate(ids)])
    compare("raster + attribute table", reference,
            sensors_of(audit(covmap, work, "rat", work / "rat.tif", sensors_json)), resolution, True, failures, RASTER_M)

    # A lon/lat raster (EPSG:4326, 0.0005 degrees: about 38 m east-west and 56 m north-south).
    run(["gdal_rasterize", "-q", "-a", "sensor", "-tr", "0.0005", "0.0005", "-ot", "Int32", "-a_nodata", "0",
         map_json, work / "lonlat.tif"])
    compare("lon/lat raster", reference, sensors_of(audit(covmap, work, "lonlat", work / "lonlat.tif", sensors_json)),
            resolution, True, failures, RASTER_M)

    # GeoPackage output in the map's CRS.
    check_geopackage("LV95 map, --format gpkg",
                     audit(covmap, work, "out_gpkg_lv95", work / "map_lv95.gpkg", sensors_json, "--format", "gpkg"),
                     2056, failures)
    check_geopackage("lon/lat map, --format gpkg",
                     audit(covmap, work, "out_gpkg_wgs84", map_json, sensors_json, "--format", "gpkg"), 4326, failures)
    # A planar map (the bundled Ticino map has no CRS): its GeoPackage says "metres, no CRS" rather
    # than leaving GeoPackage's default, an undefined geographic CRS (degrees).
    ticino = datasets / "maps" / "ticino"
    planar = audit(covmap, work, "out_gpkg_planar", ticino / "map.geojson", ticino / "sensors.geojson", "--planar",
                   "--format", "gpkg")
    info = run(["ogrinfo", "-so", planar / "audit.gpkg", "diagram"]).stdout
    if 'ENGCRS["covmap planar map (metres, no CRS)"' not in info or "GEOGCRS" in info:
        failures.append("planar map, --format gpkg: the diagram table is not in covmap's planar engineering CRS")
    else:
        print("  planar map, --format gpkg: engineering CRS in metres")

    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
