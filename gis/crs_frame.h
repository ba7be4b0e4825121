// covmap::gis CRS frames: a coordinate reference system named by the data (or by the user), made
// into the io::MapFrame covmap audits in, through PROJ.
//
// Accepted: any definition PROJ reads ("EPSG:2056", "urn:ogc:def:crs:EPSG::2056", an OGC URL, WKT1
// or WKT2, a PROJ string). A projected CRS whose axes are metres becomes a frame of kind
// kProjectedCrs: its coordinates are the plane, used as they are (east, north, whatever axis order
// the CRS's definition states); forward/inverse go to and from WGS84 through PROJ's best
// transformation for the area; point_scale_at() is the larger of the meridional and parallel
// scales there (equal for the conformal projections national grids use). A compound CRS (a
// projected one with a height) is taken by its horizontal part.
//
// Rejected with std::invalid_argument, a sentence for people that says what to do: a definition
// PROJ cannot read; a geographic CRS (lon/lat: the readers project those with covmap's own local
// projection instead); a projected CRS in other units than metres (US survey feet, say), because
// every tolerance and message of covmap is in metres ("reproject with ogr2ogr -t_srs …").
//
// Thread safety: a frame serializes its PROJ calls with a mutex of its own, so a shared frame may
// be used by several threads (PROJ objects are not re-entrant).
#pragma once

#include <memory>
#include <string>

#include "io/map_frame.h"

namespace covmap::gis {

// What a definition names, before a frame is made of it.
enum class CrsKind {
  kGeographic,  // longitude/latitude on some datum
  kProjected,   // a projection, in some linear unit
  kOther,       // geocentric, vertical, engineering: nothing covmap can place a map in
};

// The kind of the CRS a definition names; throws std::invalid_argument if PROJ cannot read it.
CrsKind crs_kind(const std::string& definition);

// The frame of a projected CRS in metres (see the contract above).
std::shared_ptr<const io::MapFrame> projected_crs_frame(const std::string& definition);

// The io::CrsResolver the readers take: projected_crs_frame for the names files declare.
io::CrsResolver proj_crs_resolver();

}  // namespace covmap::gis
