// report.html: one self-contained page (docs/FORMATS.md, "Audit reports"). Layout: summary cards,
// the details of every stage, the map picture (report/audit_html_map.h), the sortable sensor table.
// Nothing is loaded from anywhere: CSS and JavaScript are inline and the page names no URL.
#include <ostream>
#include <stdexcept>
#include <string>
#include <string_view>

#include "report/audit_html_map.h"
#include "report/audit_html_text.h"
#include "report/audit_report.h"

namespace covmap::report {
namespace {

using detail::fixed_number;
using detail::html_escape;
using detail::human_number;
using detail::sort_key;

constexpr const char* kStyle = R"css(
body{font:14px/1.45 system-ui,-apple-system,"Segoe UI",sans-serif;margin:1.5em auto;padding:0 1.5em;color:#222;max-width:1500px}
h1{font-size:1.5em;margin:0 0 .2em}h2{font-size:1.15em;margin:1.6em 0 .5em;border-bottom:1px solid #ddd;padding-bottom:.2em}
h3{font-size:1em;margin:1em 0 .3em}
code{font-size:.92em;background:#f3f3f3;padding:0 .25em;word-break:break-all}
.meta{color:#555;margin:.2em 0}
.misfit{color:#fff;background:#8e44ad;padding:.5em .8em;border-radius:4px;font-weight:bold}
.cards{display:flex;flex-wrap:wrap;gap:.6em;margin:.6em 0}
.card{border:1px solid #ddd;border-left-width:5px;border-radius:5px;padding:.4em .9em;min-width:7.5em}
.card b{display:block;font-size:1.7em;font-variant-numeric:tabular-nums}
.details{display:flex;flex-wrap:wrap;gap:0 2.5em}
table{border-collapse:collapse}td,th{padding:.2em .6em;text-align:left;border-bottom:1px solid #eee;vertical-align:top}
table.kv th{font-weight:normal;color:#555}
td.n{text-align:right;font-variant-numeric:tabular-nums;white-space:nowrap}
table.sortable th{cursor:pointer;user-select:none;background:#f5f5f5;position:sticky;top:0;white-space:nowrap}
table.sortable th[data-dir=asc]::after{content:" \25B2"}table.sortable th[data-dir=desc]::after{content:" \25BC"}
td.verdict{font-weight:600;white-space:nowrap}
tr.v-inconsistent{background:#fff3f1}
.controls label{margin-right:1.2em}
.legend span{margin-right:1.2em;white-space:nowrap}.legend i{display:inline-block;width:.8em;height:.8em;border-radius:50%;margin-right:.3em;vertical-align:-.05em}
#map{max-width:100%;height:auto;border:1px solid #ccc;background:#fbfbfb;cursor:grab;display:block;margin:.5em 0}
#map path,#map line,#map circle{vector-effect:non-scaling-stroke}
#map .cells path{stroke:none}
#map .boundaries{fill:none;stroke:#1d1d1d;stroke-width:1.2}
#map .frame{fill:none;stroke:#777;stroke-width:1}
#map .reported-diagram{fill:none;stroke:#6a3d9a;stroke-width:1.2;stroke-dasharray:5 3}
#map .shift{stroke-width:1.6}
#map .reported{fill:#fff;stroke-width:1.5}
#map .sensor{stroke:#fff;stroke-width:1}
.hidden{display:none}
ul.messages{margin:.3em 0;padding-left:1.3em}
)css";

// Sorting of the sensor table by any column, pan and zoom of the map (wheel, drag, double click
// to reset), and the layer switches. Plain ES2015, no library.
constexpr const char* kScript = R"js(
(function () {
  for (const table of document.querySelectorAll('table.sortable')) {
    const heads = Array.from(table.tHead.rows[0].cells);
    heads.forEach((th, column) => th.addEventListener('click', () => {
      const ascending = th.dataset.dir !== 'asc';
      heads.forEach(h => { delete h.dataset.dir; });
      th.dataset.dir = ascending ? 'asc' : 'desc';
      const numeric = th.dataset.type === 'num';
      const key = row => { const cell = row.cells[column]; return cell.dataset.v !== undefined ? cell.dataset.v : cell.textContent; };
      const body = table.tBodies[0];
      const rows = Array.from(body.rows);
      rows.sort((a, b) => {
        let x = key(a), y = key(b);
        if (numeric) {
          x = x === '' ? NaN : Number(x); y = y === '' ? NaN : Number(y);
          if (isNaN(x) || isNaN(y)) return isNaN(x) - isNaN(y);  // missing values last either way
          return ascending ? x - y : y - x;
        }
        return ascending ? x.localeCompare(y) : y.localeCompare(x);
      });
      rows.forEach(row => body.appendChild(row));
    }));
  }
  for (const box of document.querySelectorAll('input[data-layer]')) {
    const layer = document.getElementById(box.dataset.layer);
    if (!layer) { box.disabled = true; continue; }
    box.checked = !layer.classList.contains('hidden');
    box.addEventListener('change', () => layer.classList.toggle('hidden', !box.checked));
  }
  const svg = document.getElementById('map');
  if (!svg) return;
  const home = svg.getAttribute('viewBox').split(' ').map(Number);
  let view = home.slice();
  const show = () => svg.setAttribute('viewBox', view.join(' '));
  const toView = (x, y) => {
    const r = svg.getBoundingClientRect();
    // preserveAspectRatio meet: the picture fills the element's box in the view's aspect ratio.
    const s = Math.max(view[2] / r.width, view[3] / r.height);
    const ox = (r.width * s - view[2]) / 2, oy = (r.height * s - view[3]) / 2;
    return [view[0] + (x - r.left) * s - ox, view[1] + (y - r.top) * s - oy, s];
  };
  svg.addEventListener('wheel', e => {
    e.preventDefault();
    const [px, py] = toView(e.clientX, e.clientY);
    const f = e.deltaY < 0 ? 0.8 : 1.25;
    view = [px - (px - view[0]) * f, py - (py - view[1]) * f, view[2] * f, view[3] * f];
    show();
  }, {passive: false});
  let drag = null;
  svg.addEventListener('mousedown', e => { drag = {x: e.clientX, y: e.clientY, view: view.slice(), s: toView(0, 0)[2]}; svg.style.cursor = 'grabbing'; });
  window.addEventListener('mousemove', e => {
    if (!drag) return;
    view = [drag.view[0] - (e.clientX - drag.x) * drag.s, drag.view[1] - (e.clientY - drag.y) * drag.s, view[2], view[3]];
    show();
  });
  window.addEventListener('mouseup', () => { drag = null; svg.style.cursor = ''; });
  svg.addEventListener('dblclick', () => { view = home.slice(); show(); });
})();
)js";

// The colours of every verdict's card and table cell, from the one palette (verdict_colour) that
// also draws the map and the legend.
std::string verdict_style() {
  std::string css;
  for (const audit::SensorVerdict verdict : audit::kAllSensorVerdicts) {
    const std::string c = detail::verdict_class(verdict), colour = detail::verdict_colour(verdict);
    css += ".card." + c + "{border-left-color:" + colour + "}." + c + " td.verdict{color:" + colour + "}\n";
  }
  return css;
}

std::string count_text(std::size_t n) { return std::to_string(n); }

void card(std::ostream& out, const std::string& id, const std::string& css_class, std::size_t value, std::string_view label) {
  out << "<div class=\"card " << css_class << "\"><b id=\"" << id << "\">" << value << "</b>" << label << "</div>\n";
}

void row(std::ostream& out, const std::string& name, const std::string& value_html) {
  out << "<tr><th>" << name << "</th><td>" << value_html << "</td></tr>\n";
}

std::string id_list(const std::vector<std::string>& ids) {
  if (ids.empty()) return "none";
  std::string out;
  for (std::size_t i = 0; i < ids.size(); ++i) out += (i ? ", " : "") + std::string("<code>") + html_escape(ids[i]) + "</code>";
  return out;
}

void agreement_table(std::ostream& out, const char* title, const audit::DiagramAgreement* a) {
  out << "<div><h3>" << title << "</h3><table class=\"kv\">\n";
  if (!a) {
    row(out, "agreement", "not computed");
  } else {
    row(out, "mean IoU (area-weighted)", human_number(a->mean_iou, 4));
    row(out, "Hausdorff distance", human_number(a->hausdorff_m, 4) + " m");
    row(out, "vanished (cell in map, none recomputed)", id_list(a->vanished));
    row(out, "appeared (recomputed cell, none in map)", id_list(a->appeared));
  }
  out << "</table></div>\n";
}

void summary(std::ostream& out, const AuditReportContext& c) {
  const audit::AuditResult& r = c.result;
  const AuditVerdictCounts n = count_verdicts(r.sensors);
  out << "<section id=\"summary\"><h2>Summary</h2>\n<div class=\"cards\">\n";
  // Every sensor once: the total, then one card per verdict (zero counts too), adding up to it.
  card(out, "count-sensors", "", n.sensors, "sensors");
  for (std::size_t i = 0; i < n.by_verdict.size(); ++i) {
    const std::string css = detail::verdict_class(audit::kAllSensorVerdicts[i]);
    card(out, "count-" + css.substr(2), css, n.by_verdict[i], html_escape(verdict_words(audit::kAllSensorVerdicts[i])));
  }
  out << "</div>\n<p class=\"meta\" id=\"count-sum\">" << n.sensors << " sensors = " << n.in_map
      << " with a cell in the map + " << (n.sensors - n.in_map) << " reported without one; " << n.reported
      << " reported in all.</p>\n<div class=\"details\">\n";
  agreement_table(out, "Recomputed (refined) sensors vs map", &r.refined_agreement);
  agreement_table(out, "Reported sensors vs map", r.reported_agreement ? &*r.reported_agreement : nullptr);

  out << "<div><h3>Map</h3><table class=\"kv\">\n";
  row(out, "file", "<code>" + html_escape(c.map_file) + "</code>");
  row(out, "cells", count_text(c.map.cells.size()) + " (" + count_text(c.map.vertex_count) + " vertices)");
  if (c.map.projection) {
    row(out, "coordinates", "lon/lat, projected: " + html_escape(c.map.projection->description()));
    row(out, "worst scale distortion", human_number(c.map.max_scale_distortion, 3) +
                                           " (ratios of distances off by up to about twice this)");
  } else {
    row(out, "coordinates", "planar (metres)");
  }
  row(out, "sensors file", c.sensors_file.empty() ? "none" : "<code>" + html_escape(c.sensors_file) + "</code>");
  row(out, "path-loss exponent &alpha;", c.alpha ? human_number(*c.alpha, 6) : "not given");
  out << "</table></div>\n";

  const cleaning::CleaningReport& k = r.cleaned.report;
  out << "<div><h3>Cleaning</h3><table class=\"kv\">\n";
  row(out, "snap distance", human_number(k.snap_distance, 4) + " m");
  row(out, "bin size (estimated)", human_number(k.bin_size_estimate, 4) + " m");
  row(out, "chains / frame chains / junctions",
      count_text(k.chains) + " / " + count_text(k.frame_chains) + " / " + count_text(k.junctions));
  row(out, "repairs", "<b id=\"cleaning-repairs\">" + count_text(cleaning_repairs(k)) + "</b>: " +
                          count_text(k.gaps_closed) + " gaps closed, " + count_text(k.overlaps_resolved) +
                          " overlaps resolved, " + count_text(k.junctions_merged) + " junctions merged, " +
                          count_text(k.short_chains_dropped) + " short chains dropped, " +
                          count_text(k.nodes_snapped) + " nodes snapped");
  out << "</table></div>\n";

  out << "<div><h3>Fit</h3><table class=\"kv\">\n";
  row(out, "boundary samples", count_text(r.boundary_samples));
  row(out, "bin size used", human_number(r.bin_size_m, 4) + " m");
  row(out, "refinement", html_escape(r.refinement_summary));
  if (c.options) {
    row(out, "inconsistent when &chi;&sup2; &gt;", human_number(c.options->inconsistency_chi2, 6) + " (3 degrees of freedom)");
    row(out, "floors", human_number(c.options->position_floor_bins, 4) + " bins (" +
                           human_number(c.options->position_floor_bins * r.bin_size_m, 4) + " m), " +
                           human_number(c.options->power_floor_db, 4) + " dB");
  }
  out << "</table></div>\n</div>\n";

  if (!r.messages.empty()) {
    out << "<h3>Messages</h3><ul class=\"messages\">\n";
    for (const auto& m : r.messages) out << "<li>" << html_escape(m) << "</li>\n";
    out << "</ul>\n";
  }
  out << "</section>\n";
}

// The wall-clock times on one line of their own: the only part of the page that differs between
// runs of the same command (issue 12).
void run_timings(std::ostream& out, const audit::AuditResult& r) {
  out << "<p class=\"meta\" id=\"run-timings\">Time: " << fixed_number(r.seconds, 2) << " s";
  const char* separator = " (";
  for (const audit::StageTiming& t : r.timings) {
    out << separator << html_escape(t.stage) << " " << fixed_number(t.seconds, 3) << " s";
    separator = ", ";
  }
  out << (r.timings.empty() ? "" : ")") << "</p>\n";
}

void map_section(std::ostream& out, const AuditReportContext& c) {
  out << "<section id=\"map-section\"><h2>Map</h2>\n<div class=\"controls\">"
      << "<label><input type=\"checkbox\" data-layer=\"layer-cells\" checked> map cells</label>"
      << "<label><input type=\"checkbox\" data-layer=\"layer-diagram\" checked> recomputed diagram</label>"
      << "<label><input type=\"checkbox\" data-layer=\"layer-reported-diagram\"> reported sensors' diagram</label>"
      << "<label><input type=\"checkbox\" data-layer=\"layer-shifts\" checked> shifts</label>"
      << "<label><input type=\"checkbox\" data-layer=\"layer-sensors\" checked> sensors</label></div>\n";
  detail::write_audit_map_svg(c, out);
  out << "<p class=\"legend\">";
  for (const audit::SensorVerdict verdict : audit::kAllSensorVerdicts) {
    out << "<span><i style=\"background:" << detail::verdict_colour(verdict) << "\"></i>" << html_escape(verdict_words(verdict))
        << "</span>";
  }
  out << "<span>dots: reconstructed positions; rings: reported positions; arrows: reported &rarr; "
         "reconstructed. Wheel to zoom, drag to pan, double-click to reset; hover for details.</span></p>\n</section>\n";
}

// One numeric cell: shown for people, sorted by its exact value.
std::string num_cell(const std::optional<double>& value, int significant = 3) {
  return "<td class=\"n\" data-v=\"" + sort_key(value) + "\">" + human_number(value, significant) + "</td>";
}

void sensor_table(std::ostream& out, const AuditReportContext& c) {
  out << "<section id=\"sensors\"><h2>Sensors</h2>\n<table id=\"sensor-table\" class=\"sortable\"><thead><tr>"
      << "<th data-type=\"text\">sensor</th><th data-type=\"text\">verdict</th>"
      << "<th data-type=\"num\">position error (m)</th><th data-type=\"num\">&sigma; position (m)</th>"
      << "<th data-type=\"num\">power error (dB)</th><th data-type=\"num\">&chi;&sup2;</th>"
      << "<th data-type=\"num\">weight</th><th data-type=\"num\">power (dBm)</th>"
      << "<th data-type=\"num\">reported weight</th><th data-type=\"num\">reported power (dBm)</th>"
      << "<th data-type=\"num\">IoU refined</th><th data-type=\"num\">IoU reported</th>"
      << "<th data-type=\"text\">reason</th></tr></thead>\n<tbody>\n";
  for (const auto& s : c.result.sensors) {
    const bool compared = s.reported && s.in_map;
    const auto when = [](bool ok, double v) { return ok ? std::optional<double>(v) : std::nullopt; };
    out << "<tr class=\"" << detail::verdict_class(s.verdict) << "\"><td><code>" << html_escape(s.id) << "</code></td>"
        << "<td class=\"verdict\">" << html_escape(verdict_words(s.verdict)) << "</td>"
        << num_cell(when(compared, s.position_error_m))
        << num_cell(when(s.in_map && s.uncertainty_available, s.sigma_position_m))
        << num_cell(compared ? s.power_error_db : std::nullopt)
        << num_cell(s.chi2)
        << num_cell(when(s.in_map, s.weight), 4)
        << num_cell(s.in_map ? s.tx_power_dbm : std::nullopt, 4)
        << num_cell(s.reported ? s.reported->weight : std::nullopt, 4)
        << num_cell(s.reported ? s.reported->tx_power_dbm : std::nullopt, 4)
        << num_cell(s.iou_refined) << num_cell(s.iou_reported)
        << "<td>" << html_escape(s.reason) << "</td></tr>\n";
  }
  out << "</tbody></table>\n</section>\n";
}

}  // namespace

void write_audit_html(const AuditReportContext& c, std::ostream& out) {
  if (std::string why; !c.render.is_valid(&why)) throw std::invalid_argument("write_audit_html: " + why);
  out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      << "<title>covmap audit: " << html_escape(c.map_file) << "</title>\n<style>" << kStyle << verdict_style() << "</style>\n</head>\n<body>\n"
      << "<h1>Coverage map audit</h1>\n<p class=\"meta\">Map <code>" << html_escape(c.map_file) << "</code>";
  if (!c.sensors_file.empty()) out << ", reported sensors <code>" << html_escape(c.sensors_file) << "</code>";
  out << ". Written by <code>covmap audit</code> (report format covmap.audit/1).</p>\n";
  if (!c.command_line.empty())
    out << "<p class=\"meta\" id=\"run-command\">Command: <code>" << html_escape(c.command_line) << "</code></p>\n";
  run_timings(out, c.result);
  // The model fit first: when the map does not follow the model, every verdict below is read in
  // that light.
  if (const std::string fit = model_fit_text(c.result); !fit.empty())
    out << "<p id=\"model-fit\" class=\"" << (c.result.model_fit.misfit ? "misfit" : "meta") << "\">" << html_escape(fit)
        << "</p>\n";
  if (const std::string reach = reception_text(c.result); !reach.empty())
    out << "<p id=\"reception\" class=\"meta\">" << html_escape(reach) << "</p>\n";
  summary(out, c);
  map_section(out, c);
  sensor_table(out, c);
  out << "<script>" << kScript << "</script>\n</body>\n</html>\n";
}

}  // namespace covmap::report
