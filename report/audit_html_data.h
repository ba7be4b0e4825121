// The data block of report.html (internal to report/): everything the page's script draws and
// lists, as one JSON document embedded in <script type="application/json" id="report-data">.
// docs/FORMATS.md ("report.html") describes the members; report/html/report.js reads them.
//
//   grid       {w, h, px, m, x0, y0}: the map's grid (audit_html_map.h) is w × h units, one unit
//              is px CSS pixels at the nominal width and m map units (metres); its top left
//              corner is the map point (x0, y0)
//   lonlat     null for planar maps; else {n, lon[], lat[]}: lon/lat at the (n+1)² nodes of an
//              n × n grid over the frame, row by row from the top left, for bilinear lookup
//   basemap    null unless a tile URL was given and the map is geographic; else {url, n, west,
//              south, east, north, x[], y[]}: grid coordinates at the (n+1)² nodes of an n × n
//              lon/lat grid over the map's extent, row by row from the north-west
//   verdicts   [{key, words, colour}] in audit::kAllSensorVerdicts order
//   sensors    by column: {id: [...], name: [...], ...}, every column one value per sensor, in
//              the order of attention (sensors_by_severity). Columns: id, name, verdict (index
//              into verdicts), attention, basis, colour, x, y, rx, ry (grid; null when not drawn),
//              moved, sigma, power_error, chi2, weight, power, reported_weight, reported_power,
//              iou, iou_reported, fit_ratio (null when unknown; six significant digits), reason
//   cells      [[sensor index or -1, ring, ring, ...]] (rings encoded as in audit_html_map.h)
//   boundaries, frame, reported_boundaries: polylines of the recomputed diagram's bisectors, of its
//              frame, and of the reported sensors' diagram (null when there is none)
//
// Safe inside <script>: every '<', '>' and '&' (they can occur only inside strings) is written as
// a \u escape, so no input string can close the element; text that is not UTF-8 is repaired
// (U+FFFD) as in the rest of the page.
#pragma once

#include <string>

#include "report/audit_report.h"

namespace covmap::report::detail {

std::string audit_page_data(const AuditReportContext& context);

}  // namespace covmap::report::detail
