// The service's compiled-in files (internal to service/): the web page (service/web/index.html)
// and the API document (docs/openapi.json), embedded by CMake so the server needs no files beside
// the program and the page needs no network.
#pragma once

#include <string_view>

namespace covmap::service {

std::string_view index_html();
std::string_view openapi_json();

}  // namespace covmap::service
