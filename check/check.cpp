// check_diagram: sets up the shared context and runs the passes in dependency order.
#include "check/check.h"

#include <chrono>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "check/check_internal.h"
#include "check/check_normalization.h"

namespace covmap::check {

double diagram_scale(const Diagram& d) {
  Box box;
  for (const Site& s : d.sites)
    if (site_is_valid(s)) box.add({s.x, s.y});
  const double diag = box.empty() ? 0.0 : std::hypot(box.xmax - box.xmin, box.ymax - box.ymin);
  return diag > 0.0 && std::isfinite(diag) ? diag : 1.0;
}

namespace {

CheckReport run_checks(const Diagram& d, const CheckOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  CheckReport report;
  detail::CheckContext c(d, options, report);
  // Structure first: it decides which items the geometric passes may touch.
  detail::check_structure(c);
  detail::check_nodes(c);
  detail::check_arcs(c);
  detail::check_coverage(c);
  detail::check_crossings(c);
  report.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

}  // namespace

CheckReport check_diagram(const Diagram& d, const CheckOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw std::invalid_argument("CheckOptions: " + why);
  const detail::Normalization n = detail::normalization_for(d);
  if (!n.needed()) return run_checks(d, options);
  CheckReport report = run_checks(detail::normalized(d, n), options);
  detail::scale_back(report, n);
  return report;
}

namespace detail {

CheckContext::CheckContext(const Diagram& diagram, const CheckOptions& opts, CheckReport& out)
    : d(diagram),
      options(opts),
      report(out),
      scale(diagram_scale(diagram)),
      eps(opts.relative_tolerance * scale),
      owners(diagram.sites) {
  report.scale = scale;
  report.eps = eps;
}

void CheckContext::add(ViolationKind kind, Point where, std::string message, Violation ids) {
  ++report.counts_by_kind[static_cast<std::size_t>(kind)];
  if (report.violations.size() >= static_cast<std::size_t>(options.max_reported)) return;
  ids.kind = kind;
  ids.message = std::move(message);
  ids.x = where.x;
  ids.y = where.y;
  report.violations.push_back(std::move(ids));
}

std::string strf(const char* format, ...) {
  va_list args;
  va_start(args, format);
  va_list copy;
  va_copy(copy, args);
  const int n = std::vsnprintf(nullptr, 0, format, copy);
  va_end(copy);
  std::string out(n > 0 ? static_cast<std::size_t>(n) : 0, '\0');
  if (n > 0) std::vsnprintf(out.data(), out.size() + 1, format, args);
  va_end(args);
  return out;
}

}  // namespace detail
}  // namespace covmap::check
