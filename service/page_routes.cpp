// GET / (the web page) and GET /openapi.json (the API document), both compiled in.
#include "service/server_state.h"
#include "service/service_assets.h"

namespace covmap::service::detail {

void add_page_routes(HttpServer::State& s) {
  add_route(s, "GET", "/openapi.json", [](const httplib::Request&, httplib::Response& res) {
    res.set_content(std::string(openapi_json()), "application/json");
  });
  add_route(s, "GET", "/", [](const httplib::Request&, httplib::Response& res) {
    res.set_content(std::string(index_html()), "text/html; charset=utf-8");
  });
}

}  // namespace covmap::service::detail
