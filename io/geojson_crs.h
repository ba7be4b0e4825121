// Legacy GeoJSON "crs" members (internal to io/), shared by the coverage-map and sensor readers.
//
// RFC 7946 dropped "crs": GeoJSON is WGS84 longitude/latitude. Files written to the 2008 draft, and
// some tools today (GDAL for any CRS but WGS84), still declare one on the collection, a feature or
// a geometry. covmap accepts a declaration of WGS84 lon/lat ("urn:ogc:def:crs:OGC:1.3:CRS84",
// "EPSG:4326" and their URL and short spellings; GeoJSON writers put EPSG:4326 coordinates in
// lon/lat order too); a top-level one a CRS-aware caller resolves (resolve_top_level below: the
// positions are then x/y in that CRS); and, with --planar, any declaration the resolver does not
// know (a label), since the user then vouches for planar coordinates. Refused: a non-WGS84
// declaration that is not resolved, without --planar (the numbers are not lon/lat); and
// declarations that disagree with each other (the file mixes coordinate systems, and no single
// reading is right). "crs": null means "no declaration" and is ignored.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "io/input_error.h"
#include "io/json_fields.h"
#include "io/map_frame.h"

namespace covmap::io::detail {

struct CrsDeclaration {
  std::string path;   // JSON path of the member: "crs", "features[3].crs", "features[3].geometry.crs"
  std::string name;   // as declared ("EPSG:32632", "link https://..."), for messages
  bool wgs84 = false; // declares WGS84 longitude/latitude
  // Two declarations mean the same system iff their keys are equal (all WGS84 spellings share one).
  std::string key() const { return wgs84 ? "WGS84" : name; }
};

// Collects the declarations of one file, then judges them all at once.
class CrsDeclarations {
 public:
  // Records object["crs"] if present and not null; `path` is the object's JSON path.
  void add(const Json& object, const std::string& path);
  // The same for a member handed over as its JSON text (by a one-pass reader that does not build
  // the owner object). Throws Json::exception for text that is not JSON.
  void add_text(std::string_view crs, const std::string& path);

  // Problems with the declarations, each reported once per distinct system (a file whose 5000
  // features all declare EPSG:32632 gets one message, not 5000). Empty when all is well. With
  // `any_system` (--planar, or a CRS the caller resolved) only disagreement is a problem.
  std::vector<InputProblem> problems(bool any_system) const;

  // The name of the file's top-level declaration (the first one added, when its path is "crs")
  // if it is not WGS84: the CRS a CRS-aware reader resolves for the whole file.
  std::optional<std::string> foreign_top_level() const;

 private:
  std::vector<CrsDeclaration> declared_;
};

// What a CRS-aware reader makes of a file's top-level declaration: the frame of a non-WGS84 CRS
// when `resolve` is set and the file declares one (its positions are then x/y in that CRS), or the
// problems: a CRS covmap cannot use (the resolver's reason), or --planar given for data that
// declare a CRS the resolver accepts. With --planar a declaration the resolver refuses is only a
// label and accepted. Nothing when the file declares WGS84 or nothing, or `resolve` is empty.
struct TopLevelCrs {
  std::shared_ptr<const MapFrame> frame;
  std::vector<InputProblem> problems;
  bool plane = false;  // the file declares kPlaneCrsName: planar metres without a CRS
};
TopLevelCrs resolve_top_level(const CrsDeclarations& declarations, const CrsResolver& resolve, bool planar);

}  // namespace covmap::io::detail
