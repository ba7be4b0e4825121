// covmap::mapgen output documents: the three files of a generated coverage map, as JSON values.
//
//  map.geojson      FeatureCollection, one Feature per serving sensor, in sensor order:
//                   properties {"sensor": id, "name": name}, name only when the sensor has one
//                   (lon/lat input with a name column); geometry Polygon, or MultiPolygon when the
//                   sensor's bins form several 4-connected cells; rings closed, outer
//                   counter-clockwise, holes clockwise; coordinates [lon, lat] (RFC 7946) or, for
//                   planar output, metres with a "crs" member naming the local plane (GeoJSON 2008
//                   style, which GDAL/QGIS read).
//  sensors.geojson  FeatureCollection of Points, the sensors as the operator reports them:
//                   properties id, name (when it has one), tx_power_dbm, weight, position_sigma_m,
//                   power_sigma_db (the stated one-sigma accuracy; gross errors are not flagged, as
//                   in real lists).
//  truth.json       {"format":"covmap.mapgen-truth/1", ...}: generator settings, projection,
//                   raster, counts, and per sensor its name (when it has one), the true and the
//                   reported values and any gross error; for a model other than the multiplicative
//                   one also the model, its settings and each sensor's parameters, and for a town
//                   window its "layout" (docs in datasets/maps/README.md). Multiplicative maps of
//                   given nameless sensors keep exactly the original fields.
// Numbers are written as the shortest text that reads back to the same double, so rounded
// coordinates appear with at most coordinate_digits decimals.
#pragma once

#include <nlohmann/json.hpp>

#include "tools/mapgen/coverage_map_generator.h"

namespace covmap::mapgen {

using OrderedJson = nlohmann::ordered_json;

OrderedJson map_geojson(const CoverageMap& map);
OrderedJson sensors_geojson(const CoverageMap& map);
OrderedJson truth_json(const CoverageMap& map);

// A FeatureCollection as text with one feature per line: diffable and still valid JSON.
std::string feature_collection_text(const OrderedJson& collection);

}  // namespace covmap::mapgen
