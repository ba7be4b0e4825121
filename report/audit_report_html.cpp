// report.html: one self-contained page (docs/FORMATS.md, "Audit reports"; docs/REPORT_GUIDE.md
// reads it with a planner). The answer first: the verdict counts, the model fit, the map with the
// sensors coloured by verdict, and the sensors needing attention, worst first; then every sensor in
// a table that filters and searches; the details of the audit last, folded. The map and the table
// are drawn by the page's script (report/html/report.js) from one JSON block
// (report/audit_html_data.h). Nothing is loaded from anywhere unless the reader switches on a
// basemap the command line named.
#include <algorithm>
#include <array>
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>

#include "report/audit_html_assets.h"
#include "report/audit_html_data.h"
#include "report/audit_html_map.h"
#include "report/audit_html_text.h"
#include "report/audit_report.h"

namespace covmap::report {
namespace {

using detail::fixed_number;
using detail::html_escape;
using detail::human_number;

// The colours of every verdict's card, table row and list entry, from the one palette
// (verdict_colour) that also draws the map and the legend.
std::string verdict_style() {
  std::string css;
  for (const audit::SensorVerdict verdict : audit::kAllSensorVerdicts) {
    const std::string c = detail::verdict_class(verdict), colour = detail::verdict_colour(verdict);
    css += ".card." + c + "{border-left-color:" + colour + "}." + c + " td.verdict{color:" + colour + "}#attention li." + c +
           "{border-left-color:" + colour + "}.chip." + c + "{border-color:" + colour + "}\n";
  }
  return css;
}

std::string count_text(std::size_t n) { return std::to_string(n); }
// A value the user gave (an option), as short as it reads back exactly: "3.5", not "3.50000".
std::string as_given(double v) { return detail::sort_key(v); }

void row(std::ostream& out, const std::string& name, const std::string& value_html) {
  out << "<tr><th>" << name << "</th><td>" << value_html << "</td></tr>\n";
}

std::string id_list(const std::vector<std::string>& ids) {
  if (ids.empty()) return "none";
  std::string out;
  for (std::size_t i = 0; i < ids.size(); ++i) out += (i ? ", " : "") + std::string("<code>") + html_escape(ids[i]) + "</code>";
  return out;
}

// ------------------------------------------------------------------------------ first screen

void verdict_cards(std::ostream& out, const AuditReportContext& c) {
  const AuditVerdictCounts n = count_verdicts(c.result.sensors);
  out << "<section id=\"summary\"><div class=\"cards\">\n";
  // Every sensor once: the total, then one card per verdict (zero counts too, dimmed), adding up to it.
  out << "<div class=\"card\"><b id=\"count-sensors\">" << n.sensors << "</b>sensors</div>\n";
  for (std::size_t i = 0; i < n.by_verdict.size(); ++i) {
    const audit::SensorVerdict verdict = audit::kAllSensorVerdicts[i];
    const std::string css = detail::verdict_class(verdict);
    out << "<div class=\"card " << css << (n.by_verdict[i] == 0 ? " zero" : "") << "\"><b id=\"count-" << css.substr(2)
        << "\">" << n.by_verdict[i] << "</b>" << html_escape(verdict_words(verdict)) << "</div>\n";
  }
  out << "</div>\n<p class=\"meta\" id=\"count-sum\">" << n.sensors << " sensors = " << n.in_map
      << " with a cell in the map + " << (n.sensors - n.in_map) << " reported without one; " << n.reported
      << " reported in all.</p>\n</section>\n";
}

// What the map really draws, for a legend that names nothing else.
struct Drawn {
  std::array<bool, std::size(audit::kAllSensorVerdicts)> dot{}, ring{};
  bool shifts = false;
};

Drawn drawn_marks(const AuditReportContext& c) {
  const detail::GridFrame f = detail::grid_frame(c);
  Drawn d;
  for (const auto& s : c.result.sensors) {
    const std::size_t v = detail::verdict_index(s.verdict);
    const bool dot = s.in_map && f.drawable(s.position);
    const bool ring = s.reported && f.drawable(s.reported->position);
    d.dot[v] = d.dot[v] || dot;
    d.ring[v] = d.ring[v] || ring;
    d.shifts = d.shifts || (dot && ring);
  }
  return d;
}

void legend(std::ostream& out, const AuditReportContext& c) {
  const Drawn d = drawn_marks(c);
  out << "<ul id=\"map-legend\" class=\"legend\">";
  for (std::size_t v = 0; v < d.dot.size(); ++v) {
    if (!d.dot[v] && !d.ring[v]) continue;
    const audit::SensorVerdict verdict = audit::kAllSensorVerdicts[v];
    out << "<li data-symbol=\"" << audit::to_string(verdict) << "\" data-layer=\"sensors\"><i class=\"dot\" style=\"background:"
        << detail::verdict_colour(verdict) << "\"></i>" << html_escape(verdict_words(verdict)) << "</li>";
  }
  if (!c.map.cells.empty()) {
    out << "<li data-symbol=\"cells-by-verdict\" data-layer=\"cells\" data-colouring=\"verdict\"><i class=\"swatch\" "
           "style=\"background:linear-gradient(90deg,#b7e0c8 50%,#f3c0b8 50%)\"></i>map cell, tinted by its sensor's verdict</li>"
        << "<li data-symbol=\"cells-by-sensor\" data-layer=\"cells\" data-colouring=\"sensor\" hidden><i class=\"swatch\" "
           "style=\"background:linear-gradient(90deg,#e8a87c 33%,#85c1e9 33% 66%,#c39bd3 66%)\"></i>map cell, one colour per "
           "sensor</li>";
  }
  if (std::find(d.ring.begin(), d.ring.end(), true) != d.ring.end())
    out << "<li data-symbol=\"reported-position\" data-layer=\"sensors\"><i class=\"ring\"></i>reported position</li>";
  if (std::find(d.dot.begin(), d.dot.end(), true) != d.dot.end())
    out << "<li data-symbol=\"sensor-position\" data-layer=\"sensors\"><i class=\"dot\" style=\"background:#555\"></i>position "
           "the map implies (flagged sensors labelled)</li>";
  if (d.shifts)
    out << "<li data-symbol=\"shift\" data-layer=\"shifts\"><i class=\"line arrow\"></i>arrow from the reported position to "
           "the one the map implies</li>";
  if (!c.result.refined_diagram.arcs.empty())
    out << "<li data-symbol=\"boundary\" data-layer=\"diagram\"><i class=\"line\"></i>boundary recomputed from the map's "
           "sensors</li><li data-symbol=\"frame\" data-layer=\"diagram\"><i class=\"line frame\"></i>edge of the map</li>";
  if (c.result.reported_diagram)
    out << "<li data-symbol=\"reported-boundary\" data-layer=\"reported-diagram\"><i class=\"line dashed\"></i>boundary "
           "the reported sensors would draw</li>";
  out << "</ul>\n";
}

void map_panel(std::ostream& out, const AuditReportContext& c) {
  const bool geographic = (c.map.frame != nullptr);
  out << "<div id=\"map-panel\"><div class=\"map-toolbar\">"
      << "<label><input type=\"checkbox\" data-layer=\"cells\" checked> map cells</label>"
      << "<label><input type=\"checkbox\" data-layer=\"diagram\" checked> recomputed boundaries</label>";
  if (c.result.reported_diagram)
    out << "<label><input type=\"checkbox\" data-layer=\"reported-diagram\"> reported sensors' boundaries</label>";
  out << "<label><input type=\"checkbox\" data-layer=\"shifts\" checked> shifts</label>"
      << "<label><input type=\"checkbox\" data-layer=\"sensors\" checked> sensors</label>"
      << "<label>cells coloured by <select id=\"cell-colouring\"><option value=\"verdict\">verdict</option>"
         "<option value=\"sensor\">sensor</option></select></label>";
  if (geographic && !c.render.basemap_url.empty())
    out << "<label title=\"Loads map tiles from " << html_escape(c.render.basemap_url)
        << "\"><input type=\"checkbox\" id=\"basemap-toggle\"> basemap (online)</label>";
  out << "<span><button id=\"zoom-in\" title=\"Zoom in\">+</button><button id=\"zoom-out\" title=\"Zoom out\">&minus;</button>"
      << "<button id=\"zoom-home\" title=\"Whole map (or double-click the map)\">whole map</button></span></div>\n"
      << "<div id=\"map-view\"><canvas id=\"map-canvas\" role=\"img\" aria-label=\"coverage map with the sensors coloured by "
         "verdict\"></canvas>"
      << "<div id=\"scale-bar\" title=\"Scale"
      << (!geographic                                                     ? " (map units, metres)"
          : c.map.frame->kind() == io::FrameKind::kProjectedCrs ? " (metres of the map's CRS)"
                                                                : " (metres of the map's local projection)")
      << "\"><i></i><span></span></div><div id=\"map-coords\" title=\""
      << (geographic ? "Longitude and latitude (WGS84) under the cursor" : "Map coordinates under the cursor")
      << "\"></div><div id=\"map-tooltip\" hidden></div>"
      << "<div id=\"map-selection\" hidden><button title=\"Close\">&times;</button><div class=\"content\"></div></div></div>\n";
  legend(out, c);
  out << "<p class=\"meta\">Wheel or the buttons to zoom, drag to pan, double-click for the whole map; point at a sensor "
         "or cell for its numbers, click it (or a row below) to select it.</p>\n"
      << "<noscript><p class=\"warning\">The map and the sensor table need JavaScript.</p></noscript></div>\n";
}

// The list of sensors needing attention, worst first; the rest are in the table.
constexpr std::size_t kAttentionListed = 100;

void attention_list(std::ostream& out, const AuditReportContext& c) {
  const auto& sensors = c.result.sensors;
  std::size_t total = 0;
  for (const auto& s : sensors) total += needs_attention(s.verdict) ? 1 : 0;
  out << "<aside id=\"attention-panel\"><h2>Needs attention: <span id=\"attention-count\">" << total << "</span></h2>\n";
  if (total == 0) {
    out << "<p class=\"ok\" id=\"attention-none\">Every sensor is consistent with the map.</p></aside>\n";
    return;
  }
  out << "<ol id=\"attention\">\n";
  std::size_t listed = 0;
  for (const std::size_t i : sensors_by_severity(sensors)) {
    const audit::SensorAudit& s = sensors[i];
    if (!needs_attention(s.verdict)) continue;
    if (listed == kAttentionListed) break;
    ++listed;
    // The reason usually starts with the verdict's words; they are not repeated then.
    const std::string_view words = verdict_words(s.verdict);
    out << "<li class=\"" << detail::verdict_class(s.verdict) << "\" data-sensor-id=\"" << html_escape(s.id) << "\"><b>"
        << html_escape(s.id) << "</b>";
    if (!s.name.empty()) out << " <span class=\"name\">" << html_escape(s.name) << "</span>";
    if (s.reason.rfind(words, 0) != 0) out << " <span class=\"verdict-words\">" << html_escape(words) << "</span>";
    out << "<div class=\"why\">" << html_escape(s.reason) << "</div></li>\n";
  }
  if (listed < total)
    out << "<li class=\"more\">&hellip; and " << (total - listed) << " more: see the table below.</li>\n";
  out << "</ol></aside>\n";
}

// ------------------------------------------------------------------------------ the table

void sensor_table(std::ostream& out, const AuditReportContext& c) {
  const AuditVerdictCounts n = count_verdicts(c.result.sensors);
  out << "<section id=\"sensors\"><h2>All sensors</h2>\n<div class=\"table-controls\">";
  for (std::size_t i = 0; i < n.by_verdict.size(); ++i) {
    if (n.by_verdict[i] == 0) continue;
    const audit::SensorVerdict verdict = audit::kAllSensorVerdicts[i];
    out << "<label class=\"chip " << detail::verdict_class(verdict) << "\"><input type=\"checkbox\" name=\"verdict-filter\" value=\""
        << audit::to_string(verdict) << "\" checked> " << html_escape(verdict_words(verdict)) << " (" << n.by_verdict[i]
        << ")</label>";
  }
  out << "<button id=\"filter-attention\">needing attention</button><button id=\"filter-all\">all</button>"
      << "<input id=\"sensor-search\" type=\"search\" placeholder=\"Search by id or name\" aria-label=\"Search sensors by id or name\">"
      << "<button id=\"sort-severity\" title=\"Worst first: inconsistent, model misfit, not in the map, not reported, "
         "undetermined, consistent; within each, the largest &chi;&sup2; first\">sort worst first</button></div>\n"
      << "<p class=\"meta\" id=\"table-count\"></p>\n";
  const std::string chi2_limit =
      c.options ? as_given(c.options->inconsistency_chi2) : std::string("the threshold");
  out << "<table id=\"sensor-table\"><thead><tr>"
      << "<th data-key=\"sensor\" data-type=\"text\" title=\"The sensor's id, and its name when the input gives one\">sensor</th>"
      << "<th data-key=\"verdict\" data-type=\"text\" title=\"Sorted worst first by default\">verdict</th>"
      << "<th data-key=\"moved\" data-type=\"num\" title=\"Distance from the reported position to the position the map implies\">"
         "off by (m)</th>"
      << "<th data-key=\"sigma\" data-type=\"num\" title=\"Uncertainty (1&sigma;) of the position the map implies: how precisely "
         "the map pins the sensor down\">&plusmn; (m)</th>"
      << "<th data-key=\"power_error\" data-type=\"num\" title=\"Reported power minus the power the map implies: positive means "
         "the report says the sensor is stronger than the map shows\">power error (dB)</th>"
      << "<th data-key=\"chi2\" data-type=\"num\" title=\"How unlikely the reported position and power are, given the map; "
         "above " << chi2_limit << " the sensor is inconsistent\">&chi;&sup2;</th>"
      << "<th data-key=\"power\" data-type=\"num\" title=\"Transmit power the map implies\">power (dBm)</th>"
      << "<th data-key=\"reported_power\" data-type=\"num\" title=\"Transmit power in the sensors file\">reported (dBm)</th>"
      << "<th data-key=\"weight\" data-type=\"num\" title=\"Relative strength the map implies (strongest = 1; weight = "
         "10^(power / (10 &alpha;)))\">weight</th>"
      << "<th data-key=\"iou\" data-type=\"num\" title=\"How much of the mapped cell the recomputed cell covers (intersection "
         "over union; 100 % = the same area)\">cell overlap</th>"
      << "<th data-key=\"reason\" data-type=\"text\" title=\"Why the verdict, in one sentence\">why</th>"
      << "</tr></thead>\n<tbody></tbody></table>\n<button id=\"table-more\" hidden>show more</button>\n</section>\n";
}

// ------------------------------------------------------------------------------ details, folded

void agreement_table(std::ostream& out, const char* title, const audit::DiagramAgreement* a) {
  out << "<div><h3>" << title << "</h3><table class=\"kv\">\n";
  if (!a) {
    row(out, "agreement", "not computed (no reported sensors)");
  } else {
    row(out, "cells covered alike (area-weighted IoU)", human_number(100 * a->mean_iou, 4) + " %");
    row(out, "largest distance between boundaries", human_number(a->hausdorff_m, 4) + " m");
    row(out, "sensors with a cell in the map but none recomputed", id_list(a->vanished));
    row(out, "sensors with a recomputed cell but none in the map", id_list(a->appeared));
  }
  out << "</table></div>\n";
}

void map_and_cleaning(std::ostream& out, const AuditReportContext& c) {
  out << "<div><h3>The map</h3><table class=\"kv\">\n";
  row(out, "file", "<code>" + html_escape(c.map_file) + "</code>");
  row(out, "cells", count_text(c.map.cells.size()) + " (" + count_text(c.map.vertex_count) + " vertices)");
  if (c.map.frame) {
    const bool own_crs = c.map.frame->kind() == io::FrameKind::kProjectedCrs;
    row(out, "coordinates", std::string(own_crs ? "the map's own CRS: " : "lon/lat, projected: ") +
                                html_escape(c.map.frame->description()));
    row(out, "worst scale distortion", human_number(c.map.max_scale_distortion, 3) +
                                           " (ratios of distances off by up to about twice this)");
  } else {
    row(out, "coordinates", "planar (metres)");
  }
  row(out, "sensors file", c.sensors_file.empty() ? "none" : "<code>" + html_escape(c.sensors_file) + "</code>");
  row(out, "path-loss exponent &alpha;", c.alpha ? as_given(*c.alpha) : "not given");
  out << "</table></div>\n";

  const cleaning::CleaningReport& k = c.result.cleaned.report;
  out << "<div><h3>Cleaning the map's boundaries</h3><table class=\"kv\">\n";
  row(out, "raster cell size (estimated)", human_number(k.bin_size_estimate, 4) + " m");
  row(out, "points closer than this merged", human_number(k.snap_distance, 4) + " m");
  row(out, "boundary lines / along the map's edge / junctions",
      count_text(k.chains) + " / " + count_text(k.frame_chains) + " / " + count_text(k.junctions));
  row(out, "repairs", "<b id=\"cleaning-repairs\">" + count_text(cleaning_repairs(k)) + "</b>: " +
                          count_text(k.gaps_closed) + " gaps closed, " + count_text(k.overlaps_resolved) +
                          " overlaps resolved, " + count_text(k.junctions_merged) + " junctions merged, " +
                          count_text(k.short_chains_dropped) + " short lines dropped, " + count_text(k.nodes_snapped) +
                          " points snapped");
  out << "</table></div>\n";
}

void fit_and_thresholds(std::ostream& out, const AuditReportContext& c) {
  const audit::AuditResult& r = c.result;
  out << "<div><h3>Fitting the sensors to the map</h3><table class=\"kv\">\n";
  row(out, "points sampled along the boundaries", count_text(r.boundary_samples));
  row(out, "raster cell size used", human_number(r.bin_size_m, 4) + " m");
  row(out, "least-squares fit", r.refinement_converged ? "converged"
                                                       : "stopped before converging: positions may be less precise than stated");
  if (c.options) {
    row(out, "a sensor is inconsistent when", "&chi;&sup2; &gt; " + as_given(c.options->inconsistency_chi2) +
                                                   " (1 consistent sensor in 1000 is flagged by chance)");
    const double floor_bins = c.options->position_floor_bins;
    row(out, "smallest uncertainty assumed", human_number(floor_bins * r.bin_size_m, 4) + " m (" + as_given(floor_bins) +
                                                 (floor_bins == 1 ? " raster cell" : " raster cells") + ") and " +
                                                 as_given(c.options->power_floor_db) + " dB");
  }
  out << "</table></div>\n";
}

// The wall-clock times on one line of their own: the only part of the page that differs between
// runs of the same command (the audit is deterministic otherwise).
void run_timings(std::ostream& out, const audit::AuditResult& r) {
  out << "<p class=\"meta\" id=\"run-timings\">Time: " << fixed_number(r.seconds, 2) << " s";
  const char* separator = " (";
  for (const audit::StageTiming& t : r.timings) {
    out << separator << html_escape(t.stage) << " " << fixed_number(t.seconds, 3) << " s";
    separator = ", ";
  }
  out << (r.timings.empty() ? "" : ")") << "</p>\n";
}

void details(std::ostream& out, const AuditReportContext& c) {
  const audit::AuditResult& r = c.result;
  out << "<details id=\"details\"><summary>How the audit was made: the map, cleaning, fit, thresholds and notes</summary>\n"
      << "<div class=\"details\">\n";
  agreement_table(out, "The map against the sensors it implies", &r.refined_agreement);
  agreement_table(out, "The map against the reported sensors", r.reported_agreement ? &*r.reported_agreement : nullptr);
  map_and_cleaning(out, c);
  fit_and_thresholds(out, c);
  out << "</div>\n<h3>Notes for analysts</h3><ul class=\"messages\">\n<li>solver: " << html_escape(r.refinement_summary) << "</li>\n";
  for (const auto& m : r.messages) out << "<li>" << html_escape(m) << "</li>\n";
  out << "</ul>\n";
  if (!c.command_line.empty())
    out << "<p class=\"meta\" id=\"run-command\">Command: <code>" << html_escape(c.command_line) << "</code></p>\n";
  run_timings(out, r);
  out << "</details>\n";
}

}  // namespace

void write_audit_html(const AuditReportContext& c, std::ostream& out) {
  if (std::string why; !c.render.is_valid(&why)) throw std::invalid_argument("write_audit_html: " + why);
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      << "<title>covmap audit: " << html_escape(c.map_file) << "</title>\n<style>" << detail::kReportCss << verdict_style()
      << "</style>\n</head>\n<body>\n"
      << "<header><h1>Coverage map audit</h1>\n<p class=\"meta\">Map <code>" << html_escape(c.map_file) << "</code>";
  if (!c.sensors_file.empty()) out << ", reported sensors <code>" << html_escape(c.sensors_file) << "</code>";
  out << ". Written by <code>covmap audit</code>; docs/REPORT_GUIDE.md explains how to read it.</p></header>\n";
  // A wrong alpha and the model fit first: every verdict below is read in their light.
  if (const std::string alpha = alpha_warning_text(c.result, c.alpha); !alpha.empty())
    out << "<p id=\"alpha\" class=\"misfit\">" << html_escape(alpha) << "</p>\n";
  if (const std::string fit = model_fit_text(c.result); !fit.empty())
    out << "<p id=\"model-fit\" class=\"" << (c.result.model_fit.misfit ? "misfit" : "meta") << "\">" << html_escape(fit)
        << "</p>\n";
  if (const std::string reach = reception_text(c.result); !reach.empty())
    out << "<p id=\"reception\" class=\"meta\">" << html_escape(reach) << "</p>\n";
  verdict_cards(out, c);
  out << "<section id=\"overview\">\n";
  map_panel(out, c);
  attention_list(out, c);
  out << "</section>\n";
  sensor_table(out, c);
  details(out, c);
  out << "<script type=\"application/json\" id=\"report-data\">" << detail::audit_page_data(c) << "</script>\n"
      << "<script>" << detail::kReportJs << "</script>\n</body>\n</html>\n";
}

}  // namespace covmap::report
