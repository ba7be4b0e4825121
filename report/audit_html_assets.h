// report.html's stylesheet and script (internal to report/). They live in report/html/ as a .css
// and a .js file; the build compiles them in (report/CMakeLists.txt), and write_audit_html
// writes them inline, so the page needs nothing from anywhere.
#pragma once

namespace covmap::report::detail {

extern const char* const kReportCss;
extern const char* const kReportJs;

}  // namespace covmap::report::detail
