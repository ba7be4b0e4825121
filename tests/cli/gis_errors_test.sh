#!/usr/bin/env bash
# Inputs that parse but cannot mean what they say, and GIS inputs covmap cannot use:
# each ends with exit 2, a message naming the file and the problem (and what to do), and nothing
# written — the output folder is never created.
# Usage: gis_errors_test.sh path/to/covmap path/to/datasets
# Needs GDAL's tools (gdal-bin) to make the inputs; every covmap call runs under `timeout`.
set -u
covmap=$(realpath "$1")
datasets=$(realpath "$2")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
passed=0
failed=0
for tool in ogr2ogr gdal_rasterize gdal_translate; do
  command -v "$tool" >/dev/null || { echo "FAIL: $tool not found: install gdal-bin (scripts/setup-debian.sh)"; exit 1; }
done
bern="$datasets/maps/bern"
# refused NAME PATTERN ARGS...: covmap audit ARGS -o $work/out_NAME exits 2, says PATTERN (an
# extended regex, matched case-insensitively) and leaves no output folder.
refused() {
  local name="$1" pattern="$2"
  shift 2
  local out="$work/out_$name"
  timeout 120 "$covmap" audit "$@" -o "$out" -q >"$work/said.txt" 2>&1
  local code=$?
  if [ "$code" -eq 2 ] && grep -qiE -- "$pattern" "$work/said.txt" && [ ! -e "$out" ]; then
    passed=$((passed + 1))
  else
    failed=$((failed + 1))
    echo "FAIL: $name: exit $code (want 2), output folder $([ -e "$out" ] && echo exists || echo absent), said: $(head -c 500 "$work/said.txt")"
  fi
}

# Geographic-looking coordinates declared planar: lon/lat data labelled LV95.
ogr2ogr -f GPKG -a_srs EPSG:2056 "$work/degrees_as_lv95.gpkg" "$bern/map.geojson"
refused degrees_as_lv95 "degrees_as_lv95.gpkg.*longitude/latitude ranges.*CH1903\+ / LV95.*declare the CRS" \
  "$work/degrees_as_lv95.gpkg" --sensors "$bern/sensors.geojson" --alpha 3.5
# ... and with --planar on lon/lat GeoJSON.
refused degrees_planar "map.geojson.*longitude/latitude ranges.*--planar" "$bern/map.geojson" --planar
# The reverse: LV95 metres labelled WGS84 lon/lat.
ogr2ogr -f GPKG -t_srs EPSG:2056 "$work/lv95.gpkg" "$bern/map.geojson"
ogr2ogr -f GPKG -a_srs EPSG:4326 "$work/metres_as_wgs84.gpkg" "$work/lv95.gpkg"
refused metres_as_wgs84 "metres_as_wgs84.gpkg.*WGS 84.*longitude/latitude CRS.*not degrees.*-a_srs" \
  "$work/metres_as_wgs84.gpkg"
# Sensors far outside the map: lon/lat numbers given as LV95 x/y.
printf 'id;x;y;tx_power_dbm\na;7,45;46,95;30\nb;7,50;46,90;31\n' >"$work/degrees.csv"
refused sensors_far "degrees.csv.*2 reported sensors lie farther outside the map.*km" \
  "$work/lv95.gpkg" --sensors "$work/degrees.csv" --alpha 3.5
# Sensors with x/y against a lon/lat map and no CRS named.
printf 'id,x,y,tx_power_dbm\na,2600000,1200000,30\n' >"$work/lv95.csv"
refused xy_without_crs "lv95.csv.*x/y but the map is in lon/lat.*--sensor-crs" \
  "$bern/map.geojson" --sensors "$work/lv95.csv" --alpha 3.5
# A CRS in other units than metres (California zone 3, US survey feet).
ogr2ogr -f GPKG -t_srs EPSG:2227 "$work/feet.gpkg" "$bern/map.geojson"
refused feet "feet.gpkg.*foot.*covmap works in metres.*ogr2ogr -t_srs" "$work/feet.gpkg"
refused sensor_crs_feet "sensor-crs.*foot" "$bern/map.geojson" --sensors "$work/lv95.csv" --sensor-crs EPSG:2227 --alpha 3.5
refused sensor_crs_unknown "sensor-crs.*cannot read" "$bern/map.geojson" --sensors "$work/lv95.csv" --sensor-crs EPSG:99999999 --alpha 3.5
# A GeoJSON declaring a CRS PROJ does not know.
sed 's/"type":"FeatureCollection"/"type":"FeatureCollection","crs":{"type":"name","properties":{"name":"EPSG:99999999"}}/' \
  "$bern/map.geojson" >"$work/unknown_crs.geojson"
refused unknown_crs "unknown_crs.geojson.*crs.*cannot read" "$work/unknown_crs.geojson"
# Data without a CRS need --planar; --planar with data that declare one is refused.
ogr2ogr -f "ESRI Shapefile" "$work/nocrs.shp" "$work/lv95.gpkg" && rm "$work/nocrs.prj"
refused no_crs "nocrs.shp.*no coordinate reference system.*--planar" "$work/nocrs.shp"
refused planar_with_crs "lv95.gpkg.*CH1903\+ / LV95.*drop --planar" "$work/lv95.gpkg" --planar
ogr2ogr -f GeoJSON -lco RFC7946=NO -t_srs EPSG:2056 "$work/lv95.geojson" "$bern/map.geojson"
refused planar_with_geojson_crs "lv95.geojson.*EPSG.*2056.*drop --planar" "$work/lv95.geojson" --planar
# Several layers and none named; a layer that is not there.
ogr2ogr -f GPKG -nln other -append "$work/lv95.gpkg" "$bern/sensors.geojson" -t_srs EPSG:2056
refused layers "lv95.gpkg.*2 layers.*--layer" "$work/lv95.gpkg"
refused no_layer "lv95.gpkg.*no layer 'nope'" "$work/lv95.gpkg" --layer nope
# Rasters: a float band; values the table does not name; a band that is not there.
gdal_rasterize -q -a sensor -tr 200 200 -ot Float32 -a_nodata 0 -l map "$work/lv95.gpkg" "$work/float.tif"
refused float_band "float.tif.*Float32.*integers.*gdal_translate -ot" "$work/float.tif"
gdal_translate -q -ot Int32 "$work/float.tif" "$work/ids.tif"
printf 'value,sensor\n2657913,Zollikofen\n' >"$work/short_table.csv"
refused table_missing "ids.tif.*raster value\(s\) have no sensor in .*short_table.csv" "$work/ids.tif" --raster-table "$work/short_table.csv"
refused no_band "ids.tif.*no band 2" "$work/ids.tif" --band 2
# A file neither covmap nor GDAL reads as a map.
printf 'this is not a map\n' >"$work/notes.xyz"
refused not_a_map "notes.xyz.*neither covmap nor GDAL.*GeoPackage" "$work/notes.xyz"

echo "gis_errors: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
